/* kilolib's sensor readings from the simulator's analog inputs, printed on
 * the console (checked by ctest). */
#include <kilolib.h>

#include "openswarm/kilobot_sim.h"

static void print(const char *label_P, int16_t v) {
    sim_puts_P(label_P);
    if (v < 0) {
        sim_putc('-');
        v = (int16_t)-v;
    }
    sim_put_uint((uint16_t)v);
    sim_putc('\n');
}

void setup(void) {
    print(PSTR("light "), get_ambientlight());
    print(PSTR("voltage "), get_voltage());
    print(PSTR("temperature "), get_temperature());
    sim_exit(0);
}

void loop(void) {}

int main(void) {
    kilo_init();
    kilo_start(setup, loop);
    return 0;
}
