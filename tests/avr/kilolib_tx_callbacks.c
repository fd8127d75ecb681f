/* A classic Kilobot program whose transmit callbacks do real work, as
 * programs written for the classic library (which calls them from its
 * timer interrupt, on the main stack) may: message_tx rebuilds the message
 * through a 160-byte scratch buffer and computes its CRC; message_tx_success
 * prints. Robot 1 talks, robot 2 prints what it hears. Under OpenSwarm the
 * callbacks run as an event handler on the system stack, so this is fine;
 * on a small thread stack it would overflow, the guard
 * would stop that thread, and nothing more would be sent. */
#include <kilolib.h>
#include <string.h>
#include "debug.h"

static message_t message;
static uint8_t sent;

void setup(void) { debug_init(); }

void loop(void) {}

static message_t *message_tx(void) {
    if (kilo_uid != 1) return 0;
    volatile uint8_t scratch[160];
    for (uint8_t i = 0; i < sizeof scratch; i++) scratch[i] = (uint8_t)(sent + i);
    message.type = NORMAL;
    message.data[0] = scratch[0];
    message.data[1] = scratch[159];
    message.crc = message_crc(&message);
    return &message;
}

static void message_tx_success(void) { printf("robot %u sent %u\n", kilo_uid, ++sent); }

static void message_rx(message_t *m, distance_measurement_t *d) {
    (void)d;
    printf("robot %u heard %u,%u\n", kilo_uid, m->data[0], m->data[1]);
}

int main(void) {
    kilo_init();
    kilo_message_rx = message_rx;
    kilo_message_tx = message_tx;
    kilo_message_tx_success = message_tx_success;
    kilo_start(setup, loop);
    return 0;
}
