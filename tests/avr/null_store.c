/* A field written through a struct pointer that was never set: on the
 * AVR, data address 3 is register r3, so the store changes a register
 * instead of trapping, and the firmware goes on to stop with status 0 - it
 * passed. openswarm-sim decodes each store and fails the run at this one
 * (avr.null_store). */
#include <stdint.h>

#include "openswarm/kilobot_sim.h"

struct neighbour {
    uint8_t id;
    uint16_t distance;
    uint8_t seen;
};

static struct neighbour *volatile closest; /* never set: NULL */

int main(void) {
    closest->seen = 1;
    sim_exit(0);
    return 0;
}
