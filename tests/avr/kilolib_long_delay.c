/* A loop() that waits in one long delay(): meanwhile the robot still hears
 * the other robot's messages (its callback runs) and still sends its own,
 * and PAUSE stops the program at once, in the middle of the delay; RUN
 * starts loop() afresh (setup() ran once). (avr.kilolib_long_delay) */
#include <kilolib.h>

#include "openswarm/kernel.h"
#include "openswarm/kilobot_sim.h"

static message_t message;
static uint8_t loops, heard;

void setup(void) {
    message.type = NORMAL;
    message.data[0] = (uint8_t)kilo_uid;
    message.crc = message_crc(&message);
}

void loop(void) {
    sim_puts_P(PSTR("loop began "));
    sim_put_uint(++loops);
    sim_puts_P(PSTR("\n"));
    set_color(RGB(0, 0, 1));
    delay(60000);
    sim_puts_P(PSTR("the long delay returned\n"));
}

static message_t *message_tx(void) { return &message; }

static void message_rx(message_t *m, distance_measurement_t *d) {
    (void)d;
    if (heard++ >= 6) return;
    sim_puts_P(PSTR("heard robot "));
    sim_put_uint(m->data[0]);
    sim_puts_P(PSTR(" at "));
    sim_put_uint(Sys_Get_SystemTime());
    sim_puts_P(PSTR(" ms\n"));
}

int main(void) {
    kilo_init();
    kilo_message_tx = message_tx;
    kilo_message_rx = message_rx;
    kilo_start(setup, loop);
    return 0;
}
