/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The end of a file the run wrote (sim.h): a write that failed - a full
 * disk, /dev/full - fails the run, naming the file, instead of leaving it
 * cut short behind an exit status of 0. */
#include <errno.h>
#include <string.h>

#include "sim.h"

static int stdout_error; /* errno of the first failed flush of stdout */

void stdout_flush(void) {
    if (fflush(stdout) != 0 && stdout_error == 0) stdout_error = errno;
}

int written_close(FILE *f, const char *what, int close_it) {
    int failed = ferror(f) != 0, reason = f == stdout ? stdout_error : 0;
    clearerr(f);
    if (fflush(f) != 0) {
        failed = 1;
        if (reason == 0) reason = errno;
    }
    if (close_it && fclose(f) != 0) {
        failed = 1;
        if (reason == 0) reason = errno;
    }
    if (!failed) return 0;
    fprintf(stderr, "openswarm-sim: %s: cannot write it: %s; what the run wrote there is "
                    "incomplete: free some room on its disk, or write it elsewhere\n",
            what, reason != 0 ? strerror(reason) : "a write failed");
    return -1;
}
