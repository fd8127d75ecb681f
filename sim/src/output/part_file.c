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

FILE *part_table_open(const char *path, const char *header)
{
    char *part = part_file_name(path);
    FILE *f = part ? fopen(part, "w") : NULL;
    if (!f) {
        fprintf(stderr, "openswarm-sim: cannot write %s: %s; choose another --out folder\n",
                part ? part : path, strerror(errno));
        free(part);
        return NULL;
    }
    free(part);
    fprintf(f, "%s\n", header);
    return f;
}

int part_table_close(FILE *f, const char *path, int keep)
{
    if (!f)
        return 0;
    int bad = ferror(f);
    if (fclose(f) != 0 || bad) {
        fprintf(stderr, "openswarm-sim: cannot write %s: %s; is the disk full?\n", path,
                strerror(errno));
        part_file_finish(path, 0);
        return -1;
    }
    return part_file_finish(path, keep) != 0 && keep ? -1 : 0;
}
