/* Random numbers on simulated robots: classic rand_hard() reads the
 * temperature sensor's lowest bits, rand_soft() is seeded from it and the
 * uid. In a world the analog inputs carry noise, so each robot prints its
 * own numbers. */
#include <kilolib.h>

#include "debug.h"

void setup(void) {
    uint8_t h0 = rand_hard(), h1 = rand_hard(), h2 = rand_hard();
    uint8_t s0 = rand_soft(), s1 = rand_soft(), s2 = rand_soft();
    printf("robot %u hard %u %u %u soft %u %u %u\n", kilo_uid, h0, h1, h2, s0, s1, s2);
}

void loop(void) { delay(1000); }

int main(void) {
    kilo_init();
    debug_init();
    kilo_start(setup, loop);
    return 0;
}
