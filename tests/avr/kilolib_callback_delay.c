/* delay() in a message callback busy-waits, as the classic library's does
 * (its callbacks run in its timer interrupt): a callback here runs as an
 * event handler, which cannot sleep, and delay() returned at once there.
 * In loop(), a thread, it sleeps. (avr.kilolib_callback_delay) */
#include <kilolib.h>

#include "openswarm/kernel.h"
#include "openswarm/kilobot_sim.h"

static message_t message;
static uint8_t timed_in_loop, timed_in_callback;

static void say_took(const char *where, uint32_t from) {
    sim_puts_P(where);
    sim_put_uint(Sys_Get_SystemTime() - from);
    sim_puts_P(PSTR(" ms\n"));
}

void setup(void) {}

void loop(void) {
    uint32_t from = Sys_Get_SystemTime();
    delay(30);
    if (timed_in_loop++ < 2) say_took(PSTR("delay(30) in loop took "), from);
}

static message_t *message_tx(void) {
    message.type = NORMAL;
    message.crc = message_crc(&message);
    return &message;
}

static void message_tx_success(void) {
    if (timed_in_callback++ >= 2) return;
    uint32_t from = Sys_Get_SystemTime();
    delay(50);
    say_took(PSTR("delay(50) in a callback took "), from);
}

int main(void) {
    kilo_init();
    kilo_message_tx = message_tx;
    kilo_message_tx_success = message_tx_success;
    kilo_start(setup, loop);
    return 0;
}
