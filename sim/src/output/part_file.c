/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* Whole or absent (output_parts.h): every output is written under
 * NAME.part in its own folder and renamed to NAME once complete. A rename
 * within a folder is atomic, so a run killed at any point (kill -9, a
 * crash, the power) leaves the previous NAME or none, never half of one;
 * what it was writing stays as NAME.part. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "output/output_parts.h"

char *part_file_name(const char *path)
{
    size_t n = strlen(path) + sizeof ".part";
    char *p = malloc(n);
    if (p)
        snprintf(p, n, "%s.part", path);
    return p;
}

int part_file_finish(const char *path, int complete)
{
    char *part = part_file_name(path);
    if (!part)
        return -1;
    int rc = 0;
    if (!complete) {
        remove(part); /* its errors were reported: half a file helps no one */
        rc = -1;
    } else if (rename(part, path) != 0) {
        fprintf(stderr, "openswarm-sim: cannot put %s in place of %s: %s; the run's output is in "
                        "%s: rename it yourself, or choose another --out folder\n",
                part, path, strerror(errno), part);
        rc = -1;
    }
    free(part);
    return rc;
}
