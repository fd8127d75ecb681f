/* The system clock keeps time while IR traffic flows: two robots send a
 * message at every kilo tick they can and hear each other's; each lights
 * its LED when kilo_ticks reaches 92 (92 x 32.768 ms = 3.0147 s), and
 * counts the frames it sent and heard. A receiver or sender masks
 * interrupts for a whole frame (4.4 ms), and the ticks missed meanwhile
 * must be counted exactly: a frame that gained a millisecond made the
 * clock run 3-5% fast (avr.ir_clock). */
#include <kilolib.h>
#include "debug.h"

static message_t message;
static uint16_t sent, heard;
static uint8_t done;

void setup(void) {
    debug_init();
    kilo_tx_period = 0; /* at every kilo tick the channel is free */
    message.type = NORMAL;
    message.data[0] = (uint8_t)kilo_uid;
    message.crc = message_crc(&message);
}

void loop(void) {
    if (!done && kilo_ticks >= 92) {
        done = 1;
        set_color(RGB(0, 0, 1));
        printf("robot %u: sent %u heard %u\n", kilo_uid, sent, heard);
    }
}

static message_t *message_tx(void) { return &message; }
static void message_tx_success(void) { sent++; }
static void message_rx(message_t *m, distance_measurement_t *d) {
    (void)m;
    (void)d;
    heard++;
}

int main(void) {
    kilo_init();
    kilo_message_rx = message_rx;
    kilo_message_tx = message_tx;
    kilo_message_tx_success = message_tx_success;
    kilo_start(setup, loop);
    return 0;
}
