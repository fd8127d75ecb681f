/* A classic Kilobot program printing over the debug serial port. */
#include <kilolib.h>
#include "debug.h"

#include "openswarm/kilobot_sim.h"

void setup(void) {
    debug_init();
    printf("hello from robot %u\n", kilo_uid);
    printf("ticks per second %d\n", TICKS_PER_SEC);
    delay(10); /* let the last bytes leave the transmitter */
    sim_exit(0);
}

void loop(void) {}

int main(void) {
    kilo_init();
    kilo_start(setup, loop);
    return 0;
}
