/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The first invalid opcode a robot meets stops it (board/invalid_opcode.h
 * says how simavr 1.6 gets there). On the robot such a word is a reserved
 * instruction or one this MCU lacks: the firmware ran into data, through
 * a bad jump or a return through an overwritten stack, so the run fails as
 * a crash at that address rather than going on with it. */
#include "board/invalid_opcode.h"

void invalid_opcode_attach(robot *r) {
    r->avr->custom.data = r;
    r->at_invalid_opcode = 0;
}

void invalid_opcode_stop(avr_t *avr, uint32_t pc) {
    avr->state = cpu_Crashed;
    robot *r = avr->custom.data;
    if (r == NULL || r->at_invalid_opcode) return;
    r->state = cpu_Crashed;
    r->at_invalid_opcode = 1;
    r->invalid_opcode_pc = pc;
    r->invalid_opcode = (uint16_t)(avr->flash[pc] | avr->flash[pc + 1] << 8);
}

int invalid_opcode_report(const robot *r, const char *elf, double t) {
    if (!r->at_invalid_opcode) return 0;
    char place[400];
    fprintf(stderr, "openswarm-sim: robot %d (%s) crashed at %.6f s: an invalid opcode, 0x%04x, at %s: "
                    "the Kilobot's ATmega328P has no such instruction, so the program ran into data (a bad jump, a call "
                    "through a bad function pointer or a return through an overwritten stack); run it "
                    "with avr-gdb (openswarm run --gdb 1234), break at *0x%x and see how it got there\n",
            r->index, elf, t, (unsigned)r->invalid_opcode, code_place(elf, r->invalid_opcode_pc, place, sizeof place),
            (unsigned)r->invalid_opcode_pc);
    return 1;
}
