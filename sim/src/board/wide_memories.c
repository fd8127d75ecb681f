/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* simavr 1.6 sizes an MCU's data memory to its RAMEND and its flash to
 * FLASHEND, but lets an instruction reach past them: a load or store
 * past RAMEND is logged ("Invalid write address ... out of ram") and the
 * CPU marked crashed, yet the access is still made, into the heap past
 * avr->data (any 16-bit address, plus a displacement up to 63); LPM reads
 * avr->flash at any Z. Firmware that wrote through a wild pointer thus
 * corrupted the simulator's heap or killed it with SIGSEGV, depending on
 * what lay there (found by sim/fuzz/fuzz_sim_firmware). Both memories are
 * widened here to every address an instruction can form: the stray access
 * lands in the margin, and the run ends with the firmware's crash told. */
#include <stdlib.h>
#include <string.h>

#include "sim.h"

/* The highest address an instruction can form, with a margin: X/Y/Z or
 * SP (16 bits) plus LDD/STD's displacement (6 bits), or a pre-increment. */
#define DATA_REACH (0x10000u + 64u + 2u)
#define FLASH_REACH (0x10000u + 2u)

static uint8_t *widened(uint8_t *old, size_t old_size, size_t size, uint8_t fill) {
    uint8_t *bigger = malloc(size);
    if (bigger == NULL) return NULL;
    memset(bigger, fill, size);
    memcpy(bigger, old, old_size);
    free(old);
    return bigger;
}

int board_widen_memories(avr_t *avr) {
    uint8_t *data = widened(avr->data, avr->ramend + 1u, DATA_REACH, 0);
    if (data == NULL) return -1;
    avr->data = data;
    uint8_t *flash = widened(avr->flash, avr->flashend + 1u, FLASH_REACH, 0xff); /* erased */
    if (flash == NULL) return -1;
    avr->flash = flash;
    return 0;
}
