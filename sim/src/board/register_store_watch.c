/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* A store through a pointer into the CPU's registers. On the AVR, data
 * addresses 0x00-0x1F are r0-r31: a write through a NULL pointer (a field
 * of a NULL struct pointer, an element of a NULL array) lands in a
 * register instead of trapping, and the program goes on with a register
 * changed under it - on the robot and, before this watch, in the
 * simulator. The compiler never addresses registers through memory, and of
 * avr-libc only the EEPROM reads do, on purpose (their result goes into
 * r22-r25 through X), so any other such store is a bug: reported once, at
 * the instruction, and the run fails as on a kernel fault. Each
 * instruction is decoded before it runs (sim.h's register_store_check),
 * while its pointer register still holds the address it stores to. */
#include <string.h>

#include "sim.h"

/* Where an image's EEPROM reads are, read once per firmware file. */
typedef struct image_code {
    int symbols; /* 0: a .hex or a stripped ELF, which cannot tell its EEPROM reads: unwatched */
    uint32_t code[MAX_REGISTER_STORE_CODE][2];
    int n;
} image_code;

static void note_symbol(const char *name, uint32_t value, uint32_t size, int type, void *ctx) {
    (void)type;
    image_code *c = ctx;
    if (name != NULL) c->symbols++;
    if (name == NULL || size == 0 || strncmp(name, "eeprom_read_", strlen("eeprom_read_")) != 0 ||
        c->n == MAX_REGISTER_STORE_CODE)
        return;
    c->code[c->n][0] = value;
    c->code[c->n++][1] = value + size;
}

void register_store_watch_attach(robot *r, const char *elf_path) {
    static const char *read_path;
    static image_code code;
    firmware_symbols_once(elf_path, &read_path, note_symbol, &code, sizeof code);
    r->stored_to_register = 0;
    r->register_store_watched = code.symbols != 0;
    memcpy(r->register_store_code, code.code, sizeof code.code);
    r->n_register_store_code = code.n;
}

static int stores_on_purpose(const robot *r, uint32_t pc) {
    for (int i = 0; i < r->n_register_store_code; i++)
        if (pc >= r->register_store_code[i][0] && pc < r->register_store_code[i][1]) return 1;
    return 0;
}

static const char *const pointer_names[] = {"X", "Y", "Z"};

void register_store_report(robot *r, unsigned pointer, unsigned address) {
    if (!r->register_store_watched || r->stored_to_register || stores_on_purpose(r, r->avr->pc)) return;
    r->stored_to_register = 1;
    avr_t *avr = r->avr;
    fprintf(stderr, "openswarm-sim: %sa store through a pointer (%s) at %.6f s (PC 0x%04x) wrote data "
                    "address 0x%02x, which is register r%u: a NULL or stray pointer (the AVR maps "
                    "r0-r31 to data addresses 0x00-0x1f); `openswarm run --gdb 1234` shows where\n",
            r->console.prefix, pointer_names[pointer], (double)avr->cycle / avr->frequency,
            (unsigned)avr->pc, address, address);
}
