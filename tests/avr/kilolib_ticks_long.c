/* kilo_ticks keep the classic rate, 30.52 a second (one every 32.768 ms),
 * exactly, over minutes of tickless sleep (avr.kilolib_ticks_long): loop()
 * sleeps a minute at a time, and each time it wakes kilo_ticks are what
 * the kernel's clock says they must be (ms x 125 / 4096, rounded down), and
 * the LED it toggles shows simavr's clock agreeing. */
#include <kilolib.h>

#include "debug.h"
#include "openswarm/kernel.h"

static uint8_t minutes;

void setup(void) { debug_init(); }

void loop(void) {
    delay(60000);
    uint32_t ms = Sys_Get_SystemTime();
    uint32_t ticks = kilo_ticks;
    set_color(++minutes & 1 ? RGB(1, 0, 0) : RGB(0, 0, 0));
    printf("minute %u: kilo_ticks %lu at %lu ms: %s\n", minutes, (unsigned long)ticks,
           (unsigned long)ms, ticks == ms * 125u / 4096u ? "exact" : "WRONG");
}

int main(void) {
    kilo_init();
    kilo_start(setup, loop);
    return 0;
}
