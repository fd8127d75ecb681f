/* {{name}}: dispersion, written for the classic Kilobot API. Every robot
 * says hello; a robot that hears a neighbour closer than 60 mm turns a
 * random way by a random angle and walks on for two seconds (LED red),
 * otherwise it stays put (LED green). */
#include <kilolib.h>

#define TOO_CLOSE_MM 60
#define FORGET_TICKS TICKS_PER_SEC
#define WALK_MS 2000

message_t message;
uint8_t nearest_mm = 255;
uint32_t last_heard;

void setup(void) {
    message.type = NORMAL;
    message.data[0] = (uint8_t)kilo_uid;
    message.crc = message_crc(&message);
}

void loop(void) {
    if (kilo_ticks - last_heard > FORGET_TICKS) nearest_mm = 255;
    if (nearest_mm < TOO_CLOSE_MM) {
        set_color(RGB(3, 0, 0));
        spinup_motors();
        /* Turning always the same way would walk it in circles. */
        if (rand_soft() & 1)
            set_motors(kilo_turn_left, 0);
        else
            set_motors(0, kilo_turn_right);
        delay(250 + 6 * (uint16_t)(rand_soft() & 0x7F)); /* 0.25 to 1 s: 11 to 45 degrees */
        spinup_motors();
        set_motors(kilo_straight_left, kilo_straight_right);
        delay(WALK_MS);
    } else {
        set_color(RGB(0, 3, 0));
        set_motors(0, 0);
    }
    delay(500);
}

message_t *message_tx(void) { return &message; }

void message_rx(message_t *m, distance_measurement_t *d) {
    (void)m;
    uint8_t mm = estimate_distance(d);
    if (mm < nearest_mm || kilo_ticks - last_heard > FORGET_TICKS) nearest_mm = mm;
    last_heard = kilo_ticks;
}

int main(void) {
    kilo_init();
    kilo_message_rx = message_rx;
    kilo_message_tx = message_tx;
    kilo_start(setup, loop);
    return 0;
}
