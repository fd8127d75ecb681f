/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The files a run reads (sim.h): regular files only. A FIFO given as the
 * firmware or the world blocked the simulator forever in open(), waiting
 * for a writer (issue 30); a device or a folder is no input either. */
#include <sys/stat.h>

#include "sim.h"

/* What st is, for a message: "a FIFO (named pipe)". */
static const char *kind_of(const struct stat *st) {
    if (S_ISFIFO(st->st_mode)) return "a FIFO (named pipe), which would wait for a writer forever";
    if (S_ISDIR(st->st_mode)) return "a folder";
    if (S_ISCHR(st->st_mode)) return "a character device";
    if (S_ISBLK(st->st_mode)) return "a block device";
    if (S_ISSOCK(st->st_mode)) return "a socket";
    return "not a regular file";
}

int input_is_regular(const char *what, const char *path, const char *fix) {
    struct stat st;
    /* not there: whoever opens it says so, with the fix for a missing file */
    if (path == NULL || stat(path, &st) != 0 || S_ISREG(st.st_mode)) return 0;
    fprintf(stderr, "openswarm-sim: %s %s is %s, not a regular file: %s\n", what, path, kind_of(&st), fix);
    return -1;
}
