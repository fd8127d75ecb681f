/* The Kilobot's IR wire format, apart from the hardware that sends and
 * hears it (ir.c): a frame's CRC, and a frame rebuilt from the times of its
 * pulses. Plain C: the firmware runs it, and the host fuzzes it as it is
 * (tests/fuzz/fuzz_ir_wire.cpp). Inline functions in a header: the
 * receiver's interrupt, which must keep up with pulses one slot apart,
 * compiles them into itself as it did the code they came from (its image
 * is no larger).
 *
 * In slots of one bit time: a start pulse in slot 0 and a stop pulse in
 * slot 9 (a pulse between them means two robots started together: a
 * collision), then 12 bytes of 10 slots each: a start bit (1), 8 data bits
 * LSB first, a stop bit (1). 9 data bytes, a type, and CRC-16 CCITT
 * (avr-libc's _crc_ccitt_update, seed 0xFFFF) of those 10, low byte first. */
#ifndef OPENSWARM_KILOBOT_IR_WIRE_H
#define OPENSWARM_KILOBOT_IR_WIRE_H

#include <stdbool.h>
#include <stdint.h>

#define IR_WIRE_BIT 269u /* CPU cycles a slot at 8 MHz: 29.7 kbit/s */
#define IR_WIRE_HEADER_SLOTS 10u
#define IR_WIRE_FRAME_BYTES 12u
#define IR_WIRE_CRC_BYTES 10u /* the CRC covers the data and the type */
#define IR_WIRE_SLOTS (IR_WIRE_HEADER_SLOTS + IR_WIRE_FRAME_BYTES * 10u)
/* No pulse for this long after the last one: the frame has ended, or
 * stopped short (a frame never leaves more than 9 slots between pulses:
 * the header's, and a zero byte's start and stop bits). */
#define IR_WIRE_SILENCE (10u * IR_WIRE_BIT)

/* A frame being decoded from its pulses' times (Timer1 counts, CPU cycles,
 * wrapping at 16 bits), from its start pulse on. Slots are counted forward
 * from the start pulse, and again from the stop pulse and from each byte's
 * start bit (always a 1), as a UART does: robots' clocks differ by a
 * percent or two, which over a whole frame's 130 slots would add up to
 * more than half a slot. No division runs per pulse: one would take longer
 * than a slot. */
typedef struct ir_wire_decoder {
    uint8_t *frame;         /* IR_WIRE_FRAME_BYTES, all 0 at the start: bits are ORed in */
    uint16_t slot_time;     /* the current slot's start */
    uint16_t last_pulse;    /* the time of the last pulse */
    uint8_t slot;           /* in the header; IR_WIRE_HEADER_SLOTS once past it */
    uint8_t byte, bit;      /* past the header: which byte, which of its 10 slots */
    bool header_stopped;    /* its stop pulse came */
} ir_wire_decoder;

/* What a pulse made of the frame. */
typedef enum ir_wire_step {
    IR_WIRE_MORE,        /* a data bit, or a start or stop bit: wait for the next */
    IR_WIRE_HEADER_STOP, /* the header's stop pulse: the sender's distance reading is due */
    IR_WIRE_WHOLE,       /* the last stop bit: the frame is whole (its CRC unchecked) */
    IR_WIRE_COLLISION,   /* a pulse inside the header: two senders */
    IR_WIRE_BROKEN,      /* no header stop pulse, or pulses past the frame's end */
} ir_wire_step;

#ifdef __AVR__
#include <util/crc16.h>
#define ir_wire_crc_step _crc_ccitt_update /* avr-libc's, a few instructions of assembly */
#else
/* avr-libc's _crc_ccitt_update as its manual gives it in C (reflected
 * x^16 + x^12 + x^5 + 1), for the host. */
static inline uint16_t ir_wire_crc_step(uint16_t crc, uint8_t data) {
    data = (uint8_t)(data ^ (crc & 0xFFu));
    data = (uint8_t)(data ^ (data << 4));
    return (uint16_t)((((uint16_t)data << 8) | (crc >> 8)) ^ (uint8_t)(data >> 4) ^ ((uint16_t)data << 3));
}
#endif

/* The CRC of n bytes, seed 0xFFFF. */
static inline uint16_t ir_wire_crc(const uint8_t *bytes, uint8_t n) {
    uint16_t crc = 0xFFFF;
    while (n-- != 0) crc = ir_wire_crc_step(crc, *bytes++);
    return crc;
}

/* Its CRC bytes match its first 10: the frame may be delivered. */
static inline bool ir_wire_frame_intact(const uint8_t frame[IR_WIRE_FRAME_BYTES]) {
    uint16_t crc = (uint16_t)(frame[10] | (uint16_t)frame[11] << 8);
    return crc == ir_wire_crc(frame, IR_WIRE_CRC_BYTES);
}

/* A frame starts: its start pulse came at start. */
static inline void ir_wire_decode_start(ir_wire_decoder *d, uint16_t start, uint8_t frame[IR_WIRE_FRAME_BYTES]) {
    d->frame = frame;
    d->slot_time = start;
    d->last_pulse = start;
    d->slot = 0;
    d->byte = 0;
    d->bit = 0;
    d->header_stopped = false;
}

/* The frame's next pulse, at time: the caller waits for it until
 * IR_WIRE_SILENCE after d->last_pulse, then takes the frame as stopped
 * short. (Not after d->slot_time: a pulse from a sender whose clock is fast
 * rounds to a slot that starts after it, and a receiver that takes it
 * quickly would find Timer1 behind the grid and, in 16 bits, far past any
 * silence: found by tests/fuzz/fuzz_ir_wire.cpp, a frame from a sender 2%
 * fast lost.) */
static inline ir_wire_step ir_wire_decode_pulse(ir_wire_decoder *d, uint16_t time) {
    d->last_pulse = time;
    while ((int16_t)((uint16_t)time - d->slot_time) > (int16_t)(IR_WIRE_BIT / 2u)) {
        d->slot_time = (uint16_t)(d->slot_time + IR_WIRE_BIT);
        if (d->slot < IR_WIRE_HEADER_SLOTS)
            d->slot++;
        else if (++d->bit == 10u) {
            d->bit = 0;
            d->byte++;
        }
    }
    if (d->slot < IR_WIRE_HEADER_SLOTS - 1u) return IR_WIRE_COLLISION;
    if (d->slot == IR_WIRE_HEADER_SLOTS - 1u) {
        d->header_stopped = true;
        d->slot_time = time; /* the sender's clock, afresh */
        return IR_WIRE_HEADER_STOP;
    }
    /* Without its stop pulse the header gave no low-gain reading: the
     * distance would come from the high gain's alone. */
    if (!d->header_stopped || d->byte == IR_WIRE_FRAME_BYTES) return IR_WIRE_BROKEN;
    if (d->bit == 0u)
        d->slot_time = time; /* a start bit: the sender's clock, afresh */
    else if (d->bit <= 8u)
        d->frame[d->byte] |= (uint8_t)(1u << (d->bit - 1u));
    else if (d->byte == IR_WIRE_FRAME_BYTES - 1u)
        return IR_WIRE_WHOLE; /* the last stop bit */
    return IR_WIRE_MORE;
}

#endif
