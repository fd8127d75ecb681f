/* A classic Kilobot program, unmodified: blink red once a second. */
#include <kilolib.h>

void setup(void) {}

void loop(void) {
    set_color(RGB(1, 0, 0));
    delay(500);
    set_color(RGB(0, 0, 0));
    delay(500);
}

int main(void) {
    kilo_init();
    kilo_start(setup, loop);
    return 0;
}
