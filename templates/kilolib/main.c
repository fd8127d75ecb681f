/* {{name}}: a program for the classic Kilobot library, unchanged: under
 * OpenSwarm, setup() and loop() run on the system thread (main's stack) as
 * with the classic library, and the message callbacks are event handlers. */
#include <kilolib.h>

void setup(void) {
    spinup_motors();
    set_motors(kilo_straight_left, kilo_straight_right);
}

void loop(void) {
    set_color(RGB(0, 0, 3));
    delay(500);
    set_color(RGB(0, 0, 0));
    delay(500);
}

int main(void) {
    kilo_init();
    kilo_start(setup, loop);
    return 0;
}
