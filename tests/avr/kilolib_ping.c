/* A classic Kilobot program, unmodified: robot 1 sends its id twice a
 * second; every robot prints what it hears and how far away the sender is
 * over the debug serial port. */
#include <kilolib.h>
#include "debug.h"

message_t message;

void setup(void) {
    debug_init();
    message.type = NORMAL;
    message.data[0] = (uint8_t)kilo_uid;
    message.crc = message_crc(&message);
}

void loop(void) {}

message_t *message_tx(void) { return kilo_uid == 1 ? &message : 0; }

void message_tx_success(void) { set_color(RGB(0, 1, 0)); }

void message_rx(message_t *m, distance_measurement_t *d) {
    printf("robot %u heard robot %u at %u mm\n", kilo_uid, m->data[0], estimate_distance(d));
}

int main(void) {
    kilo_init();
    kilo_message_rx = message_rx;
    kilo_message_tx = message_tx;
    kilo_message_tx_success = message_tx_success;
    kilo_start(setup, loop);
    return 0;
}
