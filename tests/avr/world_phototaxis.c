/* Phototaxis for the world's behaviour tests (tests/world/check_phototaxis.py):
 * walk while the light grows, turn while it does not. The robot walks
 * straight for WALK_MS and compares the light at the end with the light at
 * the start. While it grew by more than RISE, and by two thirds or more of
 * what it grew in the walk before (a shrinking rise says the lamp is
 * swinging to one side), the robot keeps walking (LED green). Otherwise it
 * turns on the spot by a random 45 to 90 degrees, always the same way (its
 * own, drawn at the start), and walks again (LED red if the light fell,
 * blue if it stayed level): a few turns find the heading where it rises,
 * and where it is level everywhere (in the dark, or right under the lamp)
 * the robot walks in small loops and stays near. Only readings taken while
 * walking are compared: the light sensor sits behind the robot's centre, so
 * turning on the spot changes the reading too, the wrong way (facing away
 * from a lamp puts the sensor nearest to it). */
#include <kilolib.h>

#define SAMPLES 16       /* readings averaged: the ADC's noise is about 1 count */
#define RISE SAMPLES    /* 1 count (3.2 mV), in sums of SAMPLES readings */
#define WALK_MS 3000
#define TURN_MS_PER_DEG 22 /* at about 45 deg/s */

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
static int16_t last_rise; /* in the walk before, 0 after a turn */
static uint8_t left;      /* which way it turns */

void setup(void) {
    rand_seed(rand_hard());
    left = rand_soft() & 1;
    walk();
    before = light();
}

void loop(void) {
    delay(WALK_MS);
    int16_t now = light();
    int16_t change = now - before;
    if (change > RISE && 3 * change >= 2 * last_rise) {
        set_color(RGB(0, 3, 0));
        before = now;
        last_rise = change;
        return;
    }
    last_rise = 0;
    set_color(change < -RISE ? RGB(3, 0, 0) : RGB(0, 0, 3));
    spinup_motors();
    if (left) set_motors(kilo_turn_left, 0);
    else set_motors(0, kilo_turn_right);
    delay((uint16_t)(TURN_MS_PER_DEG * (45 + (rand_soft() >> 2) * 3 / 4))); /* 45 to 92 degrees */
    walk();
    before = light();
}

int main(void) {
    kilo_init();
    kilo_start(setup, loop);
    return 0;
}
