/* move_to_light, written the way the classic Kilobot labs are: plain `int`
 * everywhere, the light averaged over 300 readings summed in an `int`.
 * The robot walks for two seconds and compares the average light with the
 * one before: brighter, it walks on (LED green); darker or level, it turns
 * a random 30 to 100 degrees, always the same way, and walks again (LED red).
 *
 * On the Kilobot `int` has 16 bits: once the average passes 109 counts
 * (about 350 mV) the sum of 300 readings passes 32 767 and wraps, and the
 * "average" comes out negative or small - nearer the lamp looks darker.
 * The exact mode runs that; the native mode's `int` has 32 bits and does
 * not wrap, so this program walks to the lamp natively and stops short of
 * it on the robot. tests/native (native.int16_move_to_light) shows the
 * cross-check catching the difference; declare the sum `long` (32 bits on
 * the robot) and both modes agree. */
#include <kilolib.h>

#ifndef LIGHT_SUM
#define LIGHT_SUM int
#endif

int light_before = 0;
int turn_left = 0;

int sample_light(void) {
    LIGHT_SUM sum = 0;
    int number_of_samples = 0;
    while (number_of_samples < 300) {
        int sample = get_ambientlight();
        if (sample != -1) {
            sum = sum + sample;
            number_of_samples = number_of_samples + 1;
        }
    }
    return sum / 300;
}

void walk(void) {
    spinup_motors();
    set_motors(kilo_straight_left, kilo_straight_right);
}

void setup(void) {
    rand_seed(rand_hard());
    turn_left = rand_soft() & 1;
    walk();
    light_before = sample_light();
}

void loop(void) {
    delay(2000);
    int light_now = sample_light();
    if (light_now > light_before) {
        set_color(RGB(0, 3, 0));
        light_before = light_now;
        return;
    }
    set_color(RGB(3, 0, 0));
    spinup_motors();
    if (turn_left)
        set_motors(kilo_turn_left, 0);
    else
        set_motors(0, kilo_turn_right);
    delay(700 + 8 * (rand_soft() & 0xFF)); /* 0.7 to 2.7 s: about 30 to 120 degrees */
    walk();
    light_before = sample_light();
}

int main(void) {
    kilo_init();
    kilo_start(setup, loop);
    return 0;
}
