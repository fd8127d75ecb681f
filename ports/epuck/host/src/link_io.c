/* Whole-message reads and writes on the world link: a pipe hands over what
 * it has, so one message may take several reads (or writes), and a signal
 * may interrupt any of them. Unbuffered, so that each answer reaches the
 * world the moment it is written. */
#define _GNU_SOURCE
#include "link_io.h"

#include <errno.h>
#include <unistd.h>

size_t link_read(int fd, void *buffer, size_t size) {
    size_t done = 0;
    while (done < size) {
        ssize_t n = read(fd, (char *)buffer + done, size - done);
        if (n == 0 || (n < 0 && errno != EINTR)) break;
        if (n > 0) done += (size_t)n;
    }
    return done;
}

bool link_write(int fd, const void *buffer, size_t size) {
    size_t done = 0;
    while (done < size) {
        ssize_t n = write(fd, (const char *)buffer + done, size - done);
        if (n < 0 && errno != EINTR) return false;
        if (n > 0) done += (size_t)n;
    }
    return true;
}
