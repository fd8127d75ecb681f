/* kilolib's loop() with KILOLIB_IDLE_LOOP: how often it runs when it has
 * nothing to do, and how soon it sees a message. Robot 1 sends one message
 * at kilo tick 20; each robot counts its loop() calls for 30 ticks and
 * notes the kilo tick it first saw a message in, then prints both. */
#include <kilolib.h>

#include "debug.h"

message_t message;
uint32_t calls, seen_at;
volatile uint8_t heard;
uint8_t sent, done;

void setup(void) {
    message.type = NORMAL;
    message.data[0] = (uint8_t)kilo_uid;
    message.crc = message_crc(&message);
}

void loop(void) {
    if (done) return;
    calls++;
    if (heard && seen_at == 0) seen_at = kilo_ticks;
    if (kilo_ticks >= 30) {
        printf("robot %u loop calls %lu message seen at tick %lu\n", kilo_uid, (unsigned long)calls,
               (unsigned long)seen_at);
        done = 1;
    }
}

message_t *message_tx(void) { return kilo_uid == 1 && kilo_ticks >= 20 && !sent ? &message : 0; }
void message_tx_success(void) { sent = 1; }

void message_rx(message_t *m, distance_measurement_t *d) {
    (void)m;
    (void)d;
    heard = 1;
}

int main(void) {
    kilo_init();
    debug_init();
    kilo_message_rx = message_rx;
    kilo_message_tx = message_tx;
    kilo_message_tx_success = message_tx_success;
    kilo_start(setup, loop);
    return 0;
}
