/* A classic Kilobot program on a busy channel: every robot sends about ten
 * times a second. While a frame is sent or received the tick interrupt
 * cannot run; kilo_ticks must still keep up with the clock, at the classic
 * library's rate. Each robot prints its kilo_ticks against what the
 * kernel's system time gives. */
#include <kilolib.h>
#include "debug.h"

#include "openswarm/kernel.h"

message_t message;
uint16_t heard;

void setup(void) {
    debug_init();
    kilo_tx_period = 700; /* 128 us steps: every third tick, 98 ms */
    message.type = NORMAL;
    message.data[0] = (uint8_t)kilo_uid;
    message.crc = message_crc(&message);
}

void loop(void) {
    if (kilo_ticks < 3 * TICKS_PER_SEC) return;
    uint32_t ticks = kilo_ticks;
    uint32_t expected = Sys_Get_SystemTime() * 1000u / 32768u; /* a tick is 32.768 ms */
    printf("robot %u heard %u, kilo_ticks %lu, clock says %lu\n", kilo_uid, heard,
           (unsigned long)ticks, (unsigned long)expected);
    delay(5000);
}

message_t *message_tx(void) { return &message; }

void message_rx(message_t *m, distance_measurement_t *d) {
    (void)m;
    (void)d;
    heard++;
}

int main(void) {
    kilo_init();
    kilo_message_rx = message_rx;
    kilo_message_tx = message_tx;
    kilo_start(setup, loop);
    return 0;
}
