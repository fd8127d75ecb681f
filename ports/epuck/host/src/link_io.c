/* Whole-message reads and writes on the world link: a pipe hands over what
 * it has, so one message may take several reads (or writes), and a signal
 * may interrupt any of them. Unbuffered, so that each answer reaches the
 * world the moment it is written. */
#define _GNU_SOURCE
#include "link_io.h"

#include <errno.h>
#include <stdio.h>
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

int link_take_stdout(void) {
    int link = dup(STDOUT_FILENO);
    if (link < 0 || dup2(STDERR_FILENO, STDOUT_FILENO) < 0) return -1;
    setvbuf(stdout, NULL, _IOLBF, 0);
    return link;
}

const char *link_read_input(int fd, epuck_world_input *in, uint16_t *pixels) {
    static char why[128];
    size_t got = link_read(fd, in, sizeof *in);
    if (got != sizeof *in) {
        snprintf(why, sizeof why, "the input ended after %zu of an epuck_world_input's %zu bytes", got,
                 sizeof *in);
        return why;
    }
    if (in->magic != EPUCK_LINK_MAGIC) {
        snprintf(why, sizeof why, "an input begins with 0x%08X, not the magic 0x%08X (\"EPK1\")",
                 (unsigned)in->magic, (unsigned)EPUCK_LINK_MAGIC);
        return why;
    }
    size_t n = (size_t)in->frame_width * in->frame_height;
    if (n > EPUCK_LINK_MAX_PIXELS) {
        snprintf(why, sizeof why, "a frame of %u x %u pixels is larger than 640 x 480",
                 in->frame_width, in->frame_height);
        return why;
    }
    got = link_read(fd, pixels, n * sizeof *pixels);
    if (got != n * sizeof *pixels) {
        snprintf(why, sizeof why, "the input ended after %zu of a %u x %u frame's %zu bytes", got,
                 in->frame_width, in->frame_height, n * sizeof *pixels);
        return why;
    }
    return NULL;
}
