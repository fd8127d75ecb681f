/* Whole-message reads and writes on the world link's file descriptors. */
#ifndef EPUCK_LINK_IO_H
#define EPUCK_LINK_IO_H

#include <stdbool.h>
#include <stddef.h>

/* Read exactly size bytes: how many were read before end of file or an
 * error (size when all were). */
size_t link_read(int fd, void *buffer, size_t size);

/* Write exactly size bytes: false on an error. */
bool link_write(int fd, const void *buffer, size_t size);

#endif
