/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The fault log: one line per injected fault, in the order the simulator
 * injects them, each "fault t=SECONDS robot=INDEX kind=KIND" and the
 * kind's details as more key=value pairs, so a script can split on spaces
 * and '='. Faults are logged and counted on the main thread only. */
#include <errno.h>
#include <stdarg.h>
#include <string.h>

#include "faults/faults.h"

static const char *const kind_names[FAULT_KINDS] = {
    [FAULT_RESET] = "reset",           [FAULT_BROWNOUT] = "brownout",
    [FAULT_PULSE_LOST] = "pulse-lost", [FAULT_PULSE_ADDED] = "pulse-added",
    [FAULT_FRAME_CUT] = "frame-cut",   [FAULT_BLANK_CALIBRATION] = "blank-calibration",
    [FAULT_CLOCK_DRIFT] = "clock-drift",
};

static FILE *out;
static const char *out_path;
static unsigned long counts[FAULT_KINDS];

int fault_log_open(const char *path) {
    if (path == NULL) {
        out = stderr;
        return 0;
    }
    out_path = path;
    out = fopen(path, "w");
    if (out == NULL) {
        fprintf(stderr, "openswarm-sim: --fault-log %s: %s; give a file in a folder that exists\n",
                path, strerror(errno));
        return -1;
    }
    return 0;
}

void fault_log(int kind, double seconds, int index, const char *detail_format, ...) {
    counts[kind]++;
    if (out == NULL) return;
    fprintf(out, "fault t=%.6f robot=%d kind=%s", seconds, index, kind_names[kind]);
    if (detail_format != NULL && detail_format[0] != '\0') {
        va_list args;
        va_start(args, detail_format);
        fputc(' ', out);
        vfprintf(out, detail_format, args);
        va_end(args);
    }
    fputc('\n', out);
}

unsigned long fault_log_count(int kind) { return counts[kind]; }

const char *fault_kind_name(int kind) { return kind_names[kind]; }

int fault_log_close(void) {
    int status = 0;
    if (out != NULL && out != stderr) {
        char what[4200];
        snprintf(what, sizeof what, "--fault-log %s", out_path);
        status = written_close(out, what, 1);
    }
    out = NULL;
    return status;
}
