/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The main stack's worst use. main(), the interrupts and, under the
 * OpenSwarm kernel, the event handlers run on the stack that grows down
 * from RAMEND towards the RAM the image reserves (its end: _end).
 * The linker checks only that reservation, so an app whose thread stacks
 * leave the main stack no room builds and then crashes. Before the
 * firmware starts, the simulator paints the room between with a pattern;
 * at the end, the lowest byte that changed tells how deep the stack went.
 * A frame reserved deeper but never written does not show there, so the
 * worst use is the deeper of that and the lowest stack pointer the stack
 * watch saw (stack_watch.c). */
#include <string.h>

#include "sim.h"

#define PAINT 0xA5

/* What the paint needs of an image: where its RAM ends, and whether it
 * has a heap in the same room. */
typedef struct image_ram {
    uint32_t end; /* _end, a data-space address; 0: none */
    int has_malloc;
} image_ram;

static void note_symbol(const char *name, uint32_t value, uint32_t size, int type, void *ctx) {
    (void)size;
    (void)type;
    image_ram *ram = ctx;
    if (name == NULL) return;
    if (strcmp(name, "_end") == 0 && ram->end == 0) ram->end = value;
    if (strcmp(name, "malloc") == 0 && value != 0) ram->has_malloc = 1;
}

static image_ram ram_of(const char *elf_path) {
    static const char *read_path;
    static image_ram ram;
    firmware_symbols_once(elf_path, &read_path, note_symbol, &ram, sizeof ram);
    return ram;
}

void main_stack_paint(robot *r, const char *elf_path) {
    /* Unmeasured: a .hex (no symbols), or a firmware whose heap grows
     * into the same room (malloc). */
    image_ram ram = ram_of(elf_path);
    uint32_t end = ram.end;
    r->main_stack_floor = 0;
    if (end < AVR_DATA_OFFSET || end - AVR_DATA_OFFSET > r->avr->ramend || ram.has_malloc) return;
    r->main_stack_floor = (uint16_t)(end - AVR_DATA_OFFSET);
    memset(r->avr->data + r->main_stack_floor, PAINT, r->avr->ramend + 1u - r->main_stack_floor);
}

/* Bytes of the main stack used at worst (0 if it was not measured), and
 * the room it had. */
unsigned main_stack_worst(const robot *r, unsigned *room) {
    *room = r->main_stack_floor ? r->avr->ramend + 1u - r->main_stack_floor : 0;
    if (!r->main_stack_floor) return 0;
    unsigned a = r->main_stack_floor;
    while (a <= r->avr->ramend && r->avr->data[a] == PAINT) a++;
    unsigned painted = r->avr->ramend + 1u - a, by_sp = stack_watch_main_used(r);
    return by_sp > painted ? by_sp : painted; /* a frame reserved but not written: only SP shows it */
}

int main_stack_report(const robot *r, int print) {
    unsigned room, used = main_stack_worst(r, &room);
    if (room == 0) return 0;
    if (print)
        fprintf(stderr, "openswarm-sim: %smain stack: worst use %u of %u bytes\n", r->console.prefix,
                used, room);
    if (used < room) return 0;
    if (r->stack_watch.overflowed == MAIN_STACK_OVERFLOWED) return 1; /* told when it happened */
    fprintf(stderr, "openswarm-sim: %sthe main stack (main, interrupts, event handlers) ran into "
                    "the RAM the image reserves (it had %u bytes) and overwrote what lies there; give it more by lowering the "
                    "threads' \"stack\" in openswarm.json\n",
            r->console.prefix, room);
    return 1;
}
