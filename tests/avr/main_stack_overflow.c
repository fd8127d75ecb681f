/* RAM the image reserves leaves the main stack little room, and main()
 * recurses deeper than that room: the stack runs into the reserved RAM,
 * which the linker cannot see. The simulator measures the main stack's
 * worst use and fails the run saying so (avr.main_stack_overflow). */
#include <stdint.h>

#include "openswarm/kilobot_sim.h"

/* All but 128 bytes of the ATmega328P's 2 KB. */
static volatile uint8_t reserved[2048 - 128];

static uint8_t depth(uint8_t n) {
    volatile uint8_t frame[16];
    for (uint8_t i = 0; i < sizeof frame; i++) frame[i] = n; /* a frame in use, all of it */
    return n == 0 ? reserved[0] : (uint8_t)(depth((uint8_t)(n - 1)) + frame[15]);
}

int main(void) {
    reserved[0] = 1;
    uint8_t sum = depth(20); /* 20 frames of 16+ bytes: about 400 bytes */
    sim_exit(sum == 0 ? 1 : 0);
    return 0;
}
