/* A classic Kilobot program, unmodified, with a distance-based behaviour:
 * every robot sends; a robot that hears a neighbour closer than 60 mm
 * shows green and stops, otherwise it shows red and moves forward. */
#include <kilolib.h>

message_t message;
volatile uint8_t nearest = 255;

void setup(void) {
    message.type = NORMAL;
    message.data[0] = (uint8_t)kilo_uid;
    message.crc = message_crc(&message);
    spinup_motors();
}

void loop(void) {
    if (nearest < 60) {
        set_color(RGB(0, 3, 0));
        set_motors(0, 0);
    } else if (nearest != 255) {
        set_color(RGB(3, 0, 0));
        set_motors(kilo_straight_left, kilo_straight_right);
    }
    delay(100);
}

message_t *message_tx(void) { return &message; }

void message_rx(message_t *m, distance_measurement_t *d) {
    (void)m;
    nearest = estimate_distance(d);
}

int main(void) {
    kilo_init();
    kilo_message_rx = message_rx;
    kilo_message_tx = message_tx;
    kilo_start(setup, loop);
    return 0;
}
