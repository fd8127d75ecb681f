/* Phototaxis for the world's behaviour tests (tests/world/check_phototaxis.py):
 * run and tumble up the light. The robot walks straight for WALK_MS and
 * compares the light at the end with the light at the start; while it grows
 * by more than RISE it keeps walking, otherwise it turns on the spot, a
 * random way and for a random time (about 20 to 70 degrees), and walks
 * again. Only readings taken while walking are compared: the light sensor
 * sits behind the robot's centre, so turning on the spot changes the
 * reading too, the wrong way (facing away from a lamp puts the sensor
 * nearest to it). The LED is green while it walks up the light, red while
 * it turns. */
#include <kilolib.h>

#define SAMPLES 16       /* readings averaged: the ADC's noise is about 1 count */
#define RISE (SAMPLES * 3 / 2) /* 1.5 counts, in sums of SAMPLES readings */
#define WALK_MS 2000

/* The sum of SAMPLES readings; a reading lost to the IR receiver (-1) is
 * taken again. */
static int16_t light(void) {
    int16_t sum = 0;
    for (uint8_t n = 0; n < SAMPLES;) {
        int16_t v = get_ambientlight();
        if (v < 0) continue;
        sum += v;
        n++;
    }
    return sum;
}

static void walk(void) {
    spinup_motors();
    set_motors(kilo_straight_left, kilo_straight_right);
}

static int16_t before;

void setup(void) {
    rand_seed(rand_hard());
    walk();
    before = light();
}

void loop(void) {
    delay(WALK_MS);
    int16_t now = light();
    if (now - before > RISE) {
        set_color(RGB(0, 3, 0));
        before = now;
        return;
    }
    set_color(RGB(3, 0, 0));
    uint8_t r = rand_soft();
    spinup_motors();
    if (r & 1) set_motors(kilo_turn_left, 0);
    else set_motors(0, kilo_turn_right);
    delay((uint16_t)(500 + 4 * (r >> 1))); /* 0.5 to 1.5 s, at about 45 deg/s */
    walk();
    before = light();
}

int main(void) {
    kilo_init();
    kilo_start(setup, loop);
    return 0;
}
