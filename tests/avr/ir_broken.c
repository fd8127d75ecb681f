/* A frame without its header's stop pulse is broken, not a message: robot
 * uid 1 sends 5 whole frames through the IR device, each followed by the
 * same frame with the header's stop pulse left out (sent by its own slot
 * loop below, as a faulty or half-occluded sender would); robot uid 2
 * prints the distance of every frame it hears and its counters (checked
 * by avr.ir_broken). The broken ones used to be delivered, with a distance
 * from the high gain's reading alone (188 mm at 40 mm). */
#include <avr/eeprom.h>
#include <avr/interrupt.h>
#include <avr/io.h>

#include "openswarm/kernel.h"
#include "openswarm/kilobot.h"
#include "openswarm/kilobot_sim.h"

#define BIT 269u /* cycles a slot, as the wire format says */

static uint16_t uid;

static bool heard(sys_pid pid, sys_event_id e, const sys_event_data *d) {
    (void)pid;
    (void)e;
    const kilobot_ir_rx *rx = d->value;
    sim_puts_P(PSTR("heard seq "));
    sim_put_uint(rx->frame[0]);
    sim_puts_P(PSTR(" at "));
    sim_put_uint(rx->distance_mm);
    sim_puts_P(PSTR(" mm\n"));
    return true;
}

/* Slot s of a frame carries a pulse: the header's start (0) and, unless
 * left out, stop (9); then each byte's start bit, its 1 bits, its stop bit. */
static bool pulse_in(const uint8_t *frame, uint8_t s, bool header_stop) {
    if (s < 10u) return s == 0u || (s == 9u && header_stop);
    uint8_t b = (uint8_t)((s - 10u) % 10u);
    return b == 0u || b == 9u || ((frame[(s - 10u) / 10u] >> (b - 1u)) & 1u);
}

static void send_without_header_stop(const uint8_t *frame) {
    cli();
    uint16_t at = TCNT1;
    for (uint8_t s = 0; s < 130u; s++, at = (uint16_t)(at + BIT)) {
        bool pulse = pulse_in(frame, s, false); /* before the wait: a division is slow */
        while ((int16_t)(TCNT1 - at) < 0) {
        }
        if (!pulse) continue;
        PORTB |= _BV(PB0);
        __builtin_avr_delay_cycles(10);
        PORTB &= (uint8_t)~_BV(PB0);
    }
    TIFR1 = _BV(ICF1); /* our own flashes */
    sei();
}

static void print(const char *label, uint16_t value) {
    sim_puts_P(label);
    sim_put_uint(value);
}

static void talk(void *arg) {
    (void)arg;
    for (uint8_t seq = 1; seq <= 5 && uid == 1; seq++) {
        Sys_Sleep(50);
        uint8_t msg[10] = {seq};
        Sys_Send_Event(KILOBOT_EVENT_IR_TX, msg, sizeof msg);
        Sys_Sleep(50);
        uint8_t frame[KILOBOT_IR_FRAME_BYTES] = {(uint8_t)(100u + seq)};
        uint16_t crc = kilobot_crc(frame, 10);
        frame[10] = (uint8_t)crc;
        frame[11] = (uint8_t)(crc >> 8);
        send_without_header_stop(frame);
    }
    Sys_Sleep(600);
    kilobot_ir_stats ir;
    kilobot_ir_get_stats(&ir);
    print(PSTR("uid "), uid);
    print(PSTR(" received "), ir.received);
    print(PSTR(" broken "), ir.broken);
    print(PSTR(" bad_crc "), ir.bad_crc);
    sim_putc('\n');
    sim_exit(0);
}

int main(void) {
    uid = eeprom_read_word((const uint16_t *)KILOBOT_EEPROM_UID);
    Sys_Init_Kernel();
    if (kilobot_devices_init() != SYS_OK) sim_exit(2);
    Sys_Set_Processor(&kilobot_ir, kilobot_ir_with_distance, NULL);
    Sys_Subscribe_to_Event(KILOBOT_EVENT_IR_RX, SYS_PID_SYSTEM, heard, NULL);
    Sys_Start_Process_Ex(talk, NULL, 96, 0, NULL);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
