/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* ir.csv: a row per Kilobot per sample, what its IR did since the run
 * began (output_ir): its firmware's own counters, read from its RAM, and
 * the channel's for it as a receiver. Counts, not rates: a metric takes
 * differences between samples if it wants them (docs/experiments.md).
 * The firmware's fields are empty for a firmware that keeps no counters
 * (kilobot_ir_counters), so a missing count is never read as 0. Written
 * as ir.csv.part while the run goes, as trajectories.csv is. */
#include <inttypes.h>
#include <stdlib.h>
#include <string.h>

#include "output/output_parts.h"

int ir_table_open(ir_table *t, const char *path)
{
    memset(t, 0, sizeof *t);
    t->path = strdup(path);
    if (t->path)
        t->file = part_table_open(path, "time_s,robot,sent,received,refused,bad_crc,broken,"
                                        "collisions,busy,heard,lost_channel");
    if (!t->file) {
        free(t->path);
        t->path = NULL;
        return -1;
    }
    return 0;
}

static void firmware_fields(FILE *f, const output_ir *ir)
{
    for (int k = 0; k < OUTPUT_IR_FIRMWARE_COUNTERS; k++) {
        if (ir->firmware_known)
            fprintf(f, ",%u", (unsigned)ir->firmware[k]);
        else
            fputc(',', f);
    }
}

int ir_table_add(ir_table *t, int n_robots, const output_sample *s)
{
    if (!t->file || !s->ir)
        return 0;
    for (int i = 0; i < n_robots; i++) {
        const output_ir *ir = &s->ir[i];
        fprintf(t->file, "%.3f,%d", s->time_s, i);
        firmware_fields(t->file, ir);
        fprintf(t->file, ",%" PRIu64 ",%" PRIu64 "\n", ir->heard, ir->lost_channel);
    }
    if (ferror(t->file)) {
        fprintf(stderr, "openswarm-sim: cannot write %s: is the disk full?\n", t->path);
        return -1;
    }
    return 0;
}

int ir_table_close(ir_table *t, int keep)
{
    int rc = part_table_close(t->file, t->path, keep);
    free(t->path);
    memset(t, 0, sizeof *t);
    return rc;
}
