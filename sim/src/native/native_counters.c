/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* --counters PERIOD in the native mode (native_counters.h): each robot's
 * kernel counters (os_stats, which the robot's native_entry points at) and
 * its IR driver's (kilobot_ir_counters, found by symbol in the shared
 * object), read from its RAM image between windows, in the exact mode's
 * line (board/firmware_counters.c). Stack use is not the AVR's here: the
 * robot's stacks are the host's (main's 64 KB, the pool's frames as the
 * host compiler lays them out), so the line says main_stack=unmeasured
 * and thread_stacks=none rather than host figures that look like the
 * robot's. */
#include "native/native_counters.h"

#include <gelf.h>
#include <stdlib.h>
#include <string.h>

#include "native/native_swarm.h"

#define IR_COUNTER_BYTES (KILOBOT_IR_COUNTERS * 2) /* kilobot_ir_stats: seven 16-bit counters */

typedef struct ir_symbol {
    uint32_t offset, size; /* in the shared object; 0: none */
} ir_symbol;

static ir_symbol *irs;   /* each app's */
static const int *app_of; /* each robot's app */

static void note_symbol(const char *name, uint32_t value, uint32_t size, int type, void *ctx) {
    ir_symbol *s = ctx;
    if (name != NULL && type == STT_OBJECT && symbol_named(name, "kilobot_ir_counters")) {
        s->offset = value;
        s->size = size;
    }
}

void native_counters_locate(const native_apps *apps) {
    irs = calloc((size_t)apps->n, sizeof *irs);
    if (irs == NULL) return; /* counted as none: the lines say so */
    for (int a = 0; a < apps->n; a++) firmware_symbols(apps->paths[a], note_symbol, &irs[a]);
    app_of = apps->app_of;
}

/* Robot index's IR counters' bytes now, or NULL: its app keeps none; *fits
 * 0: they are not laid out as kilobot_ir_stats. */
static const uint8_t *ir_bytes(int index, int *fits) {
    ir_symbol ir = irs != NULL ? irs[app_of[index]] : (ir_symbol){0, 0};
    *fits = ir.size == IR_COUNTER_BYTES;
    if (ir.offset == 0) return NULL;
    const void *at = (const void *)(native_swarm_copy_of(index)->base + ir.offset);
    return native_swarm_robot_memory(index, at, IR_COUNTER_BYTES);
}

int native_counters_ir(int index, uint16_t out[KILOBOT_IR_COUNTERS]) {
    int fits;
    const uint8_t *bytes = ir_bytes(index, &fits);
    if (bytes == NULL || !fits) return 0;
    memcpy(out, bytes, IR_COUNTER_BYTES); /* little-endian, as the AVR's */
    return 1;
}

void native_counters_print(int n_robots, double seconds) {
    for (int i = 0; i < n_robots; i++) {
        int fits;
        printf("counters t=%.3f robot=%d", seconds, i);
        firmware_counters_print_kernel(stdout, native_swarm_robot_stats(i), 1);
        const uint8_t *ir = ir_bytes(i, &fits);
        firmware_counters_print_ir(stdout, ir, fits);
        printf(" main_stack=unmeasured thread_stacks=none\n");
    }
    stdout_flush();
}
