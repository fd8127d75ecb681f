/* Raw frames timed like the classic Kilobot library's sender, for
 * openswarm-sim --ir-log: its bits are a little longer than the format's
 * 269 cycles and it leaves a few cycles between bytes, so over a frame its
 * pulses drift far from a grid counted from the start pulse; receivers
 * count each byte from its start bit. Four frames: a good one, one with the
 * CRC's last bit flipped, one whose fifth byte has its first data bit half
 * a slot late, and a good one (checked by ctest). No kernel: Timer1 at the
 * CPU clock times every pulse, interrupts off. */
#include <util/crc16.h>

#include "openswarm/kilobot_sim.h"

#define BIT_CYCLES 271u  /* the format's bit is 269 */
#define BYTE_GAP_CYCLES 16u
#define HEADER_SLOTS 10u /* a start pulse, the stop pulse 9 slots later */
#define FRAME_BYTES 12u
#define CRC_BYTES 10u
#define NO_FAULT 0xFFu

static void wait_until(uint16_t at) {
    while ((int16_t)(TCNT1 - at) < 0) {}
}

/* A flash of the IR LED (PB0) at Timer1 time `at`. */
static void pulse_at(uint16_t at) {
    wait_until(at);
    PORTB |= _BV(PB0);
    __builtin_avr_delay_cycles(8);
    PORTB &= (uint8_t)~_BV(PB0);
}

/* One byte from Timer1 time `at`: a start bit, 8 data bits LSB first, a
 * stop bit; a 1 is a pulse. `late` delays one bit by half a slot. */
static uint16_t send_byte(uint16_t at, uint8_t value, uint8_t late) {
    uint16_t bits = (uint16_t)(value << 1 | 1u | 1u << 9);
    for (uint8_t b = 0; b < 10; b++)
        if (bits & (1u << b)) pulse_at((uint16_t)(at + b * BIT_CYCLES + (b == late ? BIT_CYCLES / 2 : 0)));
    return (uint16_t)(at + 10u * BIT_CYCLES + BYTE_GAP_CYCLES);
}

static void send_frame(uint8_t first, uint8_t crc_flip, uint8_t late_byte) {
    uint8_t frame[FRAME_BYTES] = {first, 0x5A, 0xFF, 0x00, 0x33, 0x00, 0x00, 0xC3, 0x80, 0x01};
    uint16_t crc = 0xFFFF;
    for (uint8_t i = 0; i < CRC_BYTES; i++) crc = _crc_ccitt_update(crc, frame[i]);
    crc ^= crc_flip;
    frame[CRC_BYTES] = (uint8_t)crc;
    frame[CRC_BYTES + 1] = (uint8_t)(crc >> 8);
    uint16_t at = (uint16_t)(TCNT1 + 100u);
    pulse_at(at);
    pulse_at((uint16_t)(at + (HEADER_SLOTS - 1u) * BIT_CYCLES));
    at = (uint16_t)(at + HEADER_SLOTS * BIT_CYCLES);
    for (uint8_t i = 0; i < FRAME_BYTES; i++) at = send_byte(at, frame[i], i == late_byte ? 1 : NO_FAULT);
    /* A silence between frames, as between a robot's sends. */
    for (uint8_t i = 0; i < 10; i++) wait_until((uint16_t)(TCNT1 + 30000u));
}

int main(void) {
    cli();
    DDRB |= _BV(PB0);
    TCCR1B = _BV(CS10);
    send_frame(0xB1, 0, NO_FAULT);
    send_frame(0xB2, 1, NO_FAULT);
    send_frame(0xB3, 0, 4);
    send_frame(0xB4, 0, NO_FAULT); /* a broken frame is reported when the next one starts */
    sim_exit(0);
}
