/* Orbit, written as the classic Kilobot lab's star and planet are (our
 * code, in their style: plain globals, kilolib, the lab's 40 and 60 mm),
 * for the world's behaviour tests (tests/world/check_orbit.py). The lab
 * flashes two programs; this one holds both and takes the star's part on
 * the robot whose uid is STAR_UID, so one ELF runs the whole world.
 *
 * The star stands still and keeps offering the same message. A planet
 * acts on each message it hears: nearer than TOO_CLOSE it walks straight
 * (out of the star's way); nearer than DESIRED it turns left, away;
 * farther, it turns right, toward it. With the star on its right it goes
 * round clockwise. The LED: red walking, green turning left, blue turning
 * right; the star is yellow. */
#include <kilolib.h>

#define STAR_UID 1
#define TOO_CLOSE 40 /* mm */
#define DESIRED 60   /* mm */

#define STOP 0
#define FORWARD 1
#define LEFT 2
#define RIGHT 3

message_t message;
int new_message = 0;
int distance = 0;
int motion = STOP;

/* The vibration motors need a kick to start: spin up on every change. */
void set_motion(int new_motion) {
    if (new_motion == motion) return;
    motion = new_motion;
    if (motion == STOP) {
        set_motors(0, 0);
    } else if (motion == FORWARD) {
        spinup_motors();
        set_motors(kilo_straight_left, kilo_straight_right);
    } else if (motion == LEFT) {
        spinup_motors();
        set_motors(kilo_turn_left, 0);
    } else {
        spinup_motors();
        set_motors(0, kilo_turn_right);
    }
}

void setup(void) {
    message.type = NORMAL;
    message.data[0] = 0;
    message.crc = message_crc(&message);
    if (kilo_uid == STAR_UID) set_color(RGB(3, 3, 0));
}

void loop(void) {
    if (kilo_uid == STAR_UID || !new_message) return;
    new_message = 0;
    if (distance < TOO_CLOSE) {
        set_motion(FORWARD);
        set_color(RGB(3, 0, 0));
    } else if (distance < DESIRED) {
        set_motion(LEFT);
        set_color(RGB(0, 3, 0));
    } else {
        set_motion(RIGHT);
        set_color(RGB(0, 0, 3));
    }
}

message_t *message_tx(void) {
    if (kilo_uid == STAR_UID) return &message;
    return 0;
}

void message_rx(message_t *m, distance_measurement_t *d) {
    (void)m;
    new_message = 1;
    distance = estimate_distance(d);
}

int main(void) {
    kilo_init();
    kilo_message_rx = message_rx;
    kilo_message_tx = message_tx;
    kilo_start(setup, loop);
    return 0;
}
