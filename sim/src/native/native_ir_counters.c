/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* A native robot's firmware IR counters (native_ir_counters.h). The
 * object's dynamic symbols are its entry alone (robot.map), so the
 * counters are found by name in its symbol table, as an offset from where
 * it is loaded, and read from the robot's RAM image (in its copy while it
 * is loaded, else saved). */
#include "native/native_ir_counters.h"

#include <gelf.h>
#include <string.h>

#include "native/native_swarm.h"

typedef struct ir_counters_symbol {
    uint32_t offset, size; /* offset 0: not found */
} ir_counters_symbol;

static void note_symbol(const char *name, uint32_t value, uint32_t size, int type, void *ctx) {
    ir_counters_symbol *s = ctx;
    if (name != NULL && type == STT_OBJECT && symbol_named(name, "kilobot_ir_counters")) {
        s->offset = value;
        s->size = size;
    }
}

int native_ir_counters(int index, const char *so, uint16_t out[KILOBOT_IR_COUNTERS]) {
    static const char *read_path;
    static ir_counters_symbol symbol;
    firmware_symbols_once(so, &read_path, note_symbol, &symbol, sizeof symbol);
    if (symbol.offset == 0 || symbol.size != KILOBOT_IR_COUNTERS * sizeof(uint16_t)) return 0;
    const void *at = (const void *)(native_swarm_copy_of(index)->base + symbol.offset);
    const void *now = native_swarm_robot_memory(index, at, symbol.size);
    if (now == NULL) return 0;
    memcpy(out, now, symbol.size);
    return 1;
}
