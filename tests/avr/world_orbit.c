/* Orbit, a classic Kilobot exercise, for the world's behaviour tests
 * (tests/world/check_orbit.py). The robot with uid 1 is the star: it stays
 * still and sends a message every half second. Every other robot is a
 * planet: it measures its distance to the star from each message and keeps
 * it near ORBIT_MM, going round counter-clockwise (the star on its left):
 * too close, it turns right, away; too far, it turns left, toward the
 * star; in the band it walks straight. The LED shows the choice: red too
 * close, blue too far, green in the band; off when the star is not heard. */
#include <kilolib.h>

#define STAR_UID 1
#define ORBIT_MM 60
#define BAND_MM 5          /* straight within ORBIT_MM +- BAND_MM */
#define LOST_TICKS (2 * TICKS_PER_SEC) /* no message for this long: stop */

enum motion { STOP, FORWARD, LEFT, RIGHT };

static message_t message;
static volatile uint8_t heard;     /* a new distance is waiting */
static volatile uint8_t distance;  /* mm, from the last message */
static uint32_t last_heard;
static uint8_t motion = STOP;

/* Vibration motors need a kick to start: spin up at every change. */
static void set_motion(uint8_t m) {
    if (m == motion) return;
    motion = m;
    if (m == STOP) {
        set_motors(0, 0);
        return;
    }
    spinup_motors();
    if (m == FORWARD) set_motors(kilo_straight_left, kilo_straight_right);
    else if (m == LEFT) set_motors(kilo_turn_left, 0);
    else set_motors(0, kilo_turn_right);
}

void setup(void) {
    message.type = NORMAL;
    message.data[0] = 0;
    message.crc = message_crc(&message);
    if (kilo_uid == STAR_UID) set_color(RGB(3, 3, 0));
}

void loop(void) {
    if (kilo_uid == STAR_UID) {
        delay(1000); /* asleep; kilolib sends the message */
        return;
    }
    if (heard) {
        heard = 0;
        last_heard = kilo_ticks;
        uint8_t d = distance;
        if (d < ORBIT_MM - BAND_MM) {
            set_motion(RIGHT);
            set_color(RGB(3, 0, 0));
        } else if (d > ORBIT_MM + BAND_MM) {
            set_motion(LEFT);
            set_color(RGB(0, 0, 3));
        } else {
            set_motion(FORWARD);
            set_color(RGB(0, 3, 0));
        }
    } else if (motion != STOP && kilo_ticks - last_heard > LOST_TICKS) {
        set_motion(STOP);
        set_color(RGB(0, 0, 0));
    }
    delay(20);
}

static message_t *message_tx(void) { return kilo_uid == STAR_UID ? &message : 0; }

static void message_rx(message_t *m, distance_measurement_t *d) {
    (void)m;
    distance = estimate_distance(d);
    heard = 1;
}

int main(void) {
    kilo_init();
    kilo_message_rx = message_rx;
    kilo_message_tx = message_tx;
    kilo_start(setup, loop);
    return 0;
}
