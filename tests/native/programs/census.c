/* A classic kilolib program, as the labs write them: plain globals, a
 * loop() that spins on kilo_ticks (no delay()), printf on the debug port.
 * Each robot sends its uid; once a second it prints what it heard - how
 * many messages, from how many robots - how often loop() ran, and the IR
 * counters. Natively every robot's globals are its own, and the spin lets
 * time pass (tests/native/check_census.py). */
#include <debug.h>
#include <kilolib.h>
#include <stdio.h>

#include "openswarm/kilobot.h"

message_t message;
uint32_t last_report;
uint32_t loops;
uint16_t heard;
uint8_t senders[8];
uint8_t n_senders;

void setup(void) {
    message.type = NORMAL;
    message.data[0] = (uint8_t)kilo_uid;
    message.crc = message_crc(&message);
    last_report = kilo_ticks;
}

void loop(void) {
    loops++;
    if (kilo_ticks < last_report + TICKS_PER_SEC) return;
    last_report = kilo_ticks;
    kilobot_ir_stats s;
    kilobot_ir_get_stats(&s);
    printf("uid %u tick %lu: %u messages from %u robots, %lu loops, sent %u\n", kilo_uid,
           (unsigned long)kilo_ticks, heard, n_senders, (unsigned long)loops, s.sent);
}

message_t *message_tx(void) { return &message; }

void message_rx(message_t *m, distance_measurement_t *d) {
    (void)d;
    heard++;
    for (uint8_t i = 0; i < n_senders; i++)
        if (senders[i] == m->data[0]) return;
    if (n_senders < sizeof senders) senders[n_senders++] = m->data[0];
}

int main(void) {
    kilo_init();
    debug_init();
    kilo_message_rx = message_rx;
    kilo_message_tx = message_tx;
    kilo_start(setup, loop);
    return 0;
}
