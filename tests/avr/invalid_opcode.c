/* An invalid opcode (0x00c0, reserved), as code reached by a wild jump
 * runs: simavr 1.6 logs it and steps over it, and the firmware went on
 * to stop with status 0. openswarm-sim stops the robot there as crashed
 * (exit 3) (avr.invalid_opcode). Found by sim/fuzz/fuzz_sim_firmware,
 * where such code printed 100000 lines in 20 ms of simulated time. */
#include "openswarm/kilobot_sim.h"

int main(void) {
    __asm__ volatile(".word 0x00c0");
    sim_exit(0);
    return 0;
}
