/* A classic Kilobot program, unmodified, timing its messages: each robot
 * sets kilo_tx_period by its uid (1: the default, 2: 255, 3: 20000, 4: 0)
 * and prints the kilo tick at which each message went out. */
#include <kilolib.h>
#include "debug.h"

message_t message;

void setup(void) {
    debug_init();
    if (kilo_uid == 2) kilo_tx_period = 255;
    if (kilo_uid == 3) kilo_tx_period = 20000;
    if (kilo_uid == 4) kilo_tx_period = 0;
    message.type = NORMAL;
    message.crc = message_crc(&message);
}

void loop(void) {}

message_t *message_tx(void) { return &message; }

void message_tx_success(void) {
    printf("robot %u period %u sent at tick %lu\n", kilo_uid, kilo_tx_period,
           (unsigned long)kilo_ticks);
}

int main(void) {
    kilo_init();
    kilo_message_tx = message_tx;
    kilo_message_tx_success = message_tx_success;
    kilo_start(setup, loop);
    return 0;
}
