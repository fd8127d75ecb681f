/* A store through a wild pointer, past the ATmega328P's RAM (0x8FF), and
 * a program-memory read past its flash (0x7FFF). simavr 1.6 logs the
 * store and marks the CPU crashed but still makes it, into the
 * simulator's heap 60 KB past its data memory; LPM reads its flash array
 * at any address. openswarm-sim widens both memories
 * (sim/src/board/wide_memories.c): the run ends with the crash told, exit
 * 3 (avr.wild_store). Found by sim/fuzz/fuzz_sim_firmware. */
#include <avr/pgmspace.h>
#include <stdint.h>

#include "openswarm/kilobot_sim.h"

static volatile uint16_t far_away = 0xF000;

int main(void) {
    volatile uint8_t past_flash = pgm_read_byte((uint16_t)0xFFFF);
    (void)past_flash;
    for (uint16_t a = far_away; a != 0; a++) *(volatile uint8_t *)a = 0x5a;
    sim_exit(0);
    return 0;
}
