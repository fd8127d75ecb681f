/* A classic Kilobot program, unmodified: show who it is, go straight for
 * two seconds with its own calibration, then turn left. */
#include <kilolib.h>

void setup(void) {
    set_color(kilo_uid == 42 ? RGB(0, 0, 3) : RGB(3, 0, 0));
    spinup_motors();
    set_motors(kilo_straight_left, kilo_straight_right);
}

void loop(void) {
    if (kilo_ticks > 2 * TICKS_PER_SEC) set_motors(kilo_turn_left, 0);
}

int main(void) {
    kilo_init();
    kilo_start(setup, loop);
    return 0;
}
