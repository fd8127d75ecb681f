/* A classic Kilobot program, written as the labs write them (plain
 * globals, kilolib's callbacks): every robot sends its uid twice a second
 * and prints, for every message it hears, who sent it and what
 * estimate_distance makes of it. Robots standing still at known distances
 * show the error of the distance estimates (world.distance_error,
 * check_distances.py). message_rx only notes what it heard: it may run in
 * an interrupt, and loop() prints. */
#include <kilolib.h>
#include "debug.h"

#define HEARD_ROOM 16

message_t message;
volatile uint8_t heard_uid[HEARD_ROOM], heard_mm[HEARD_ROOM];
volatile uint8_t heard_in, heard_out;

void setup(void) {
    debug_init();
    message.type = NORMAL;
    message.data[0] = (uint8_t)kilo_uid;
    message.crc = message_crc(&message);
}

void loop(void) {
    while (heard_out != heard_in) {
        printf("heard %u at %u mm\n", heard_uid[heard_out], heard_mm[heard_out]);
        heard_out = (uint8_t)((heard_out + 1) % HEARD_ROOM);
    }
}

message_t *message_tx(void) { return &message; }

void message_rx(message_t *m, distance_measurement_t *d) {
    uint8_t next = (uint8_t)((heard_in + 1) % HEARD_ROOM);
    if (next == heard_out) return; /* full: loop() is behind */
    heard_uid[heard_in] = m->data[0];
    heard_mm[heard_in] = (uint8_t)estimate_distance(d);
    heard_in = next;
}

int main(void) {
    kilo_init();
    kilo_message_rx = message_rx;
    kilo_message_tx = message_tx;
    kilo_start(setup, loop);
    return 0;
}
