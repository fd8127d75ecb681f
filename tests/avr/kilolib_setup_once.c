/* A classic Kilobot program, unmodified, telling when setup() runs: once
 * per power-up or reset, whatever pauses the overhead controller makes.
 * setup() counts its runs in a static, which only a reset starts afresh;
 * loop() reports the count and kilo_ticks four times a second. */
#include <kilolib.h>
#include "debug.h"

static uint8_t setups;

void setup(void) {
    debug_init();
    setups++;
    printf("setup %u at tick %lu\n", setups, (unsigned long)kilo_ticks);
}

void loop(void) {
    printf("loop, setups %u, tick %lu\n", setups, (unsigned long)kilo_ticks);
    delay(250);
}

int main(void) {
    kilo_init();
    kilo_start(setup, loop);
    return 0;
}
