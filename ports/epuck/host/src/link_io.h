/* Whole-message reads and writes on the world link's file descriptors
 * (both ends: the robot's, here, and the world simulator's). */
#ifndef EPUCK_LINK_IO_H
#define EPUCK_LINK_IO_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "openswarm/epuck_world_link.h"

#define EPUCK_LINK_MAX_PIXELS (640u * 480u) /* the camera's full frame */

/* Read exactly size bytes: how many were read before end of file or an
 * error (size when all were). */
size_t link_read(int fd, void *buffer, size_t size);

/* Write exactly size bytes: false on an error. */
bool link_write(int fd, const void *buffer, size_t size);

/* The robot's end: the link keeps the original standard output (its fd,
 * -1 if that fails); the program's printf goes to standard error instead,
 * line by line, where it cannot corrupt a message. */
int link_take_stdout(void);

/* The next input from fd, and the pixels of its frame, if it has one
 * (at most EPUCK_LINK_MAX_PIXELS), into pixels: NULL, or why the link is
 * broken (a message in a static buffer). */
const char *link_read_input(int fd, epuck_world_input *in, uint16_t *pixels);

#endif
