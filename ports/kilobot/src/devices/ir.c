/* Infrared messages on the wire: the Kilobot's only way to talk to its
 * neighbours (the HAL device above it is ir_device.c).
 *
 * Frames go out as flashes of the IR LED on PB0, in the wire format of
 * ir_wire.h; the receivers see them through the analog comparator (AIN0
 * PD6, AIN1 PD7), whose output is wired to Timer1's input capture, so each
 * edge is timestamped by the hardware. The distance readings are sampled
 * at the header: ADC0 (high gain) from the start pulse, ADC1 (low gain)
 * from the stop pulse.
 *
 * This lower layer moves frames; the Rx processor checks the CRC and the
 * Tx processor adds it (ir_device.c). */
#include "openswarm/kilobot.h"
#include "openswarm/port.h"

#include <avr/interrupt.h>
#include <avr/io.h>
#include <string.h>

#include "devices_internal.h"
#include "ir_wire.h"

#define BIT IR_WIRE_BIT
#define TX_PIN _BV(PB0)

_Static_assert(IR_WIRE_FRAME_BYTES == KILOBOT_IR_FRAME_BYTES, "the wire's frame is the API's");

static volatile uint8_t receiving; /* carrier sense for the transmitter */


void kilobot_ir_start(void) {
    DDRB |= TX_PIN;
    PORTB &= (uint8_t)~TX_PIN;
    TCCR1A = 0;
    TCCR1B = _BV(ICES1) | _BV(CS10); /* free running at F_CPU, capture on rising edges */
    ACSR = _BV(ACIC);                /* comparator output -> input capture */
    TIFR1 = _BV(ICF1);
    TIMSK1 = _BV(ICIE1);
    receiving = 0;
}

/* The tick cannot run while a frame keeps interrupts masked. Every wait
 * loop of the frame's code takes the tick's compare flag (Timer0) as it
 * comes and counts it, so each tick that fell in the frame is counted once:
 * the ones counted before the frame's end are given after it, any later one
 * is left to the interrupt. (The elapsed time divided by a tick's length,
 * as before, gained a tick in 3 frames of 5: 4.4 ms hold 4 or 5 ticks by
 * phase, and one is left pending either way: the clock ran 3-5% fast while
 * messages flowed.) */
static uint8_t ticks_missed;

static inline void take_missed_tick(void) {
    if (TIFR0 & _BV(OCF0A)) {
        TIFR0 = _BV(OCF0A);
        ticks_missed++;
    }
}

/* os_isr_enter credits the milliseconds slept before the frame first
 * (tickless idle). */
static void catch_up_ticks(void) {
    take_missed_tick();
    if (ticks_missed == 0) return;
    os_isr_enter();
    for (; ticks_missed != 0; ticks_missed--) kilobot_tick(); /* kilolib's kilo_ticks too */
    os_isr_exit();
}

/* Next edge's Timer1 time, or -1 when none comes within IR_WIRE_SILENCE
 * of the last one. Edges are latched by the input capture hardware, so
 * polling loses none. */
static int32_t next_edge(uint16_t last) {
    for (;;) {
        take_missed_tick();
        if (TIFR1 & _BV(ICF1)) {
            uint16_t t = ICR1;
            TIFR1 = _BV(ICF1);
            return t;
        }
        if ((uint16_t)(TCNT1 - last) > (uint16_t)IR_WIRE_SILENCE) return -1;
    }
}

/* A frame that is no message - broken, or two senders' collided - counts
 * once: the rest of its pulses are let pass until the channel is quiet,
 * or each would start another reception and count again (a pulse lost
 * from a header made a dozen collisions of one frame). */
static bool discard(uint16_t *counter, uint16_t last_edge) {
    kilobot_ir_count(counter);
    for (int32_t edge = last_edge; edge >= 0; edge = next_edge((uint16_t)edge)) {
    }
    return false;
}

/* Decode one frame, interrupts masked throughout (4.4 ms, as the classic
 * library does): another interrupt in the middle would make us miss the
 * edges of two consecutive 1 bits. */
static bool receive_frame(uint16_t start, kilobot_ir_rx *rx) {
    ir_wire_decoder d;
    memset(rx, 0, sizeof *rx);
    ir_wire_decode_start(&d, start, rx->frame);
    /* A sensor reading the ADC now loses it (it reads -1, busy); its
     * conversion ends first, within 104 us: long before the stop pulse. */
    kilobot_adc_start(KILOBOT_ADC_IR_HIGH_GAIN);
    for (;;) {
        int32_t edge = next_edge(d.last_pulse);
        if (edge < 0) { /* the frame stopped short */
            kilobot_ir_count(&kilobot_ir_counters.broken);
            return false;
        }
        switch (ir_wire_decode_pulse(&d, (uint16_t)edge)) {
        case IR_WIRE_MORE: break;
        case IR_WIRE_HEADER_STOP: /* the gains are the sender's */
            rx->high_gain = kilobot_adc_take();
            kilobot_adc_start(KILOBOT_ADC_IR_LOW_GAIN);
            break;
        case IR_WIRE_WHOLE: rx->low_gain = kilobot_adc_take(); return true;
        case IR_WIRE_COLLISION: return discard(&kilobot_ir_counters.collisions, (uint16_t)edge);
        case IR_WIRE_BROKEN: return discard(&kilobot_ir_counters.broken, (uint16_t)edge);
        }
    }
}

ISR(TIMER1_CAPT_vect) {
    uint16_t start = ICR1;
    TIFR1 = _BV(ICF1);
    /* Asleep with the tick stopped, the tick's flag counts nothing: the
     * tick is back before the frame's wait loops count it. The kernel's
     * bookkeeping of the sleep waits for the frame's end. */
    kilobot_tickless_stop();
    kilobot_ir_rx rx;
    receiving = 1;
    bool whole = receive_frame(start, &rx);
    receiving = 0;
    catch_up_ticks();
    if (whole) kilobot_ir_deliver(&rx);
}

/* A flash of about 1.5 us, longer than any instruction a receiver may be
 * executing when it starts. */
static void flash(void) {
    PORTB |= TX_PIN;
    __builtin_avr_delay_cycles(10);
    PORTB &= (uint8_t)~TX_PIN;
}

/* Waits on Timer1, interrupts masked: every slot boundary is exact. */
static void send_slots(const uint8_t *frame) {
    uint16_t t0 = TCNT1;
    uint16_t at = t0;
    for (uint8_t slot = 0; slot < IR_WIRE_SLOTS; slot++, at = (uint16_t)(at + BIT)) {
        uint8_t one;
        if (slot < IR_WIRE_HEADER_SLOTS) {
            one = slot == 0u || slot == IR_WIRE_HEADER_SLOTS - 1u;
        } else {
            uint8_t s = (uint8_t)(slot - IR_WIRE_HEADER_SLOTS), bit = s % 10u;
            one = bit == 0u || bit == 9u || ((frame[s / 10u] >> (bit - 1u)) & 1u);
        }
        while ((int16_t)(TCNT1 - at) < 0) take_missed_tick();
        if (one) flash();
    }
}

sys_status kilobot_ir_transmit(const uint8_t frame[KILOBOT_IR_FRAME_BYTES]) {
    uint8_t sreg = SREG;
    cli();
    if (receiving || (TIFR1 & _BV(ICF1))) { /* carrier sense: someone is talking */
        kilobot_ir_count(&kilobot_ir_counters.busy);
        SREG = sreg;
        return SYS_E_QUEUE_FULL;
    }
    send_slots(frame);
    /* Our own flashes (their reflection, on a robot; simavr also captures
     * PB0, the LED's pin, as ICP1) latched the capture flag: taken as a
     * frame's start, they would hold us deaf in a bogus reception for a
     * whole frame time, just as the robot that waited for us answers. */
    TIFR1 = _BV(ICF1);
    kilobot_ir_count(&kilobot_ir_counters.sent);
    catch_up_ticks();
    SREG = sreg;
    return SYS_OK;
}
