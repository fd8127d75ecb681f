/* A classic Kilobot program, unmodified: every robot sends its id and
 * counts whom it heard; collisions and garbled frames must never reach
 * message_rx (checked by ctest on the printed counts). */
#include <kilolib.h>
#include "debug.h"

message_t message;
uint8_t heard[8];
uint8_t strangers;

void setup(void) {
    debug_init();
    message.type = NORMAL;
    message.data[0] = (uint8_t)kilo_uid;
    message.crc = message_crc(&message);
}

void loop(void) {
    if (kilo_ticks > 4 * TICKS_PER_SEC) {
        printf("robot %u heard 1:%u 2:%u 3:%u strangers:%u\n", kilo_uid, heard[1], heard[2],
               heard[3], strangers);
        for (;;) delay(1000);
    }
}

message_t *message_tx(void) { return &message; }

void message_rx(message_t *m, distance_measurement_t *d) {
    (void)d;
    if (m->data[0] >= 1 && m->data[0] <= 3 && m->data[0] != kilo_uid)
        heard[m->data[0]]++;
    else
        strangers++;
}

int main(void) {
    kilo_init();
    kilo_message_rx = message_rx;
    kilo_message_tx = message_tx;
    kilo_start(setup, loop);
    return 0;
}
