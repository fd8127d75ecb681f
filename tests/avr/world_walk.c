/* A classic Kilobot program for the world's motion tests: what it does
 * depends on its uid's last digit. 1: spin up, walk straight with its own
 * calibration; 2: spin up, turn left; 3: spin up, then both motors below
 * any stall duty; 4: the straight duties without spinning up first. */
#include <kilolib.h>

void setup(void) {
    switch (kilo_uid % 10) {
    case 1:
        spinup_motors();
        set_motors(kilo_straight_left, kilo_straight_right);
        break;
    case 2:
        spinup_motors();
        set_motors(kilo_turn_left, 0);
        break;
    case 3:
        spinup_motors();
        set_motors(20, 20);
        break;
    case 4: set_motors(kilo_straight_left, kilo_straight_right); break;
    default: break;
    }
}

void loop(void) { delay(1000); } /* asleep: the tests run fast */

int main(void) {
    kilo_init();
    kilo_start(setup, loop);
    return 0;
}
