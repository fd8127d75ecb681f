/* A classic Kilobot program, unmodified: a hop count from robot 1. Robot 1
 * is 0 hops away; any other robot is one hop more than the fewest it hears
 * announced. The LED shows the count: red 0, green 1, blue 2, white 3 or
 * more, off while unknown. Robots placed beyond each other's IR range
 * (openswarm-sim --line, --positions) make the count grow along a chain. */
#include <kilolib.h>

#define ORIGIN_UID 1
#define UNKNOWN 255

message_t message;
volatile uint8_t hops = UNKNOWN;
volatile uint8_t announced = UNKNOWN; /* the count message holds */

void setup(void) {
    message.type = NORMAL;
    if (kilo_uid == ORIGIN_UID) hops = 0;
}

/* The message changes only here, as in classic programs: message_tx runs
 * on a small stack (an interrupt in the classic library) and only points
 * at it. A frame sent while it changes fails its CRC and is dropped by
 * the receivers; the next one carries the new count. */
void loop(void) {
    static const uint8_t colours[] = {RGB(3, 0, 0), RGB(0, 3, 0), RGB(0, 0, 3), RGB(3, 3, 3)};
    uint8_t h = hops;
    if (h != announced) {
        message.data[0] = h;
        message.crc = message_crc(&message);
        announced = h;
    }
    set_color(h == UNKNOWN ? RGB(0, 0, 0) : colours[h < 3 ? h : 3]);
    delay(50);
}

message_t *message_tx(void) { return announced == UNKNOWN ? 0 : &message; }

void message_rx(message_t *m, distance_measurement_t *d) {
    (void)d;
    if (m->data[0] != UNKNOWN && m->data[0] + 1 < hops) hops = (uint8_t)(m->data[0] + 1);
}

int main(void) {
    kilo_init();
    kilo_message_rx = message_rx;
    kilo_message_tx = message_tx;
    kilo_start(setup, loop);
    return 0;
}
