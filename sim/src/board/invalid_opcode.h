/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* A robot stopped at the first invalid opcode it meets, as crashed, and
 * the run's report naming the opcode and its address.
 *
 * simavr 1.6 logs an invalid opcode and goes on. Most it steps over, so
 * the robot is stopped from its log line (board/firmware.c's logger), one
 * instruction later. Three it carries out on a core without the register
 * they need: ELPM and EIJMP/EICALL on the ATmega328P, which has no RAMPZ
 * nor EIND, take r0 (data address 0, where "no such register" points) as
 * the top byte of their address - ELPM then reads up to 16 MB past the
 * flash (SIGSEGV, found by sim/fuzz/fuzz_sim_firmware). Those are caught
 * before they run (lockstep.c). */
#ifndef OPENSWARM_SIM_INVALID_OPCODE_H
#define OPENSWARM_SIM_INVALID_OPCODE_H

#include "sim.h"

/* Robot r's MCU leads back to r, for the logger, which is given the MCU. */
void invalid_opcode_attach(robot *r);

/* Whether the instruction at the PC is one simavr 1.6 would carry out
 * though this core lacks it. Inline: it runs at every instruction. */
static inline int invalid_opcode_ahead(const avr_t *avr) {
    uint16_t op = (uint16_t)(avr->flash[avr->pc] | avr->flash[avr->pc + 1] << 8);
    if ((op & 0xFE0Eu) == 0x9006u || op == 0x95D8u) return avr->rampz == 0; /* ELPM */
    if ((op & 0xFEFFu) == 0x9419u) return avr->eind == 0;                  /* EIJMP, EICALL */
    return 0;
}

/* Stop the robot whose MCU is avr (crashed) at the invalid opcode at pc. */
void invalid_opcode_stop(avr_t *avr, uint32_t pc);

/* If robot r stopped at an invalid opcode: say so (its firmware's file
 * elf, t seconds into the run) and return 1. */
int invalid_opcode_report(const robot *r, const char *elf, double t);

#endif
