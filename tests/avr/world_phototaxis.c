/* Move to light, written as the classic Kilobot lab is (our code, in its
 * style: plain globals, kilolib, the lab's thresholds), for the world's
 * behaviour tests (tests/world/check_phototaxis.py).
 *
 * The robot only ever turns. It turns left until the light it averages
 * over 300 readings falls below DARK counts (the lamp has gone behind the
 * battery), then right until it rises above BRIGHT counts (the lamp is in
 * view again), and so on: swinging either side of the edge of its own
 * shadow, it creeps along the heading where the lamp comes and goes, and
 * that heading keeps the lamp ahead and to the right, so the robot closes
 * in on it. The LED shows the way it turns: red left, blue right. The
 * sum is a `long`: 300 readings of up to 1023 pass a 16-bit `int`. */
#include <kilolib.h>

#define DARK 300
#define BRIGHT 600
#define SAMPLES 300

#define TURNING_LEFT 0
#define TURNING_RIGHT 1

int turning = TURNING_LEFT;
int light = 0;

void read_light(void) {
    long total = 0;
    int taken = 0;
    while (taken < SAMPLES) {
        int reading = get_ambientlight();
        if (reading != -1) { /* -1: the IR receiver had the ADC */
            total = total + reading;
            taken = taken + 1;
        }
    }
    light = total / SAMPLES;
}

void turn_left(void) {
    spinup_motors();
    set_motors(kilo_turn_left, 0);
    set_color(RGB(3, 0, 0));
}

void turn_right(void) {
    spinup_motors();
    set_motors(0, kilo_turn_right);
    set_color(RGB(0, 0, 3));
}

void setup(void) {
    turning = TURNING_LEFT;
    turn_left();
}

void loop(void) {
    read_light();
    if (turning == TURNING_LEFT && light < DARK) {
        turning = TURNING_RIGHT;
        turn_right();
    } else if (turning == TURNING_RIGHT && light > BRIGHT) {
        turning = TURNING_LEFT;
        turn_left();
    }
}

int main(void) {
    kilo_init();
    kilo_start(setup, loop);
    return 0;
}
