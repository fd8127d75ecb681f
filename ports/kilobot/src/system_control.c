/* The Kilobot's ways out of a running program, for the overhead
 * controller's BOOT and RESET (kilolib's and the port's own, for
 * OpenSwarm-API apps): the IR bootloader, and a restart from scratch that
 * leaves the next run a mark. */
#include <avr/interrupt.h>
#include <avr/io.h>

#include "openswarm/kilobot.h"

/* The Kilobot's IR bootloader lives in the ATmega328P's 4 KB boot section,
 * from byte address 0x7000 to the end of the flash. */
#define BOOTLOADER_ADDRESS 0x7000

/* Kept by the jump: the C runtime clears .bss, not .noinit. */
static uint16_t restart_mark __attribute__((section(".noinit")));

/* The bootloader sets up the timers and interrupts it uses itself, but an
 * interrupt of ours left enabled and pending (the IR input capture) would
 * enter its vector table, where no handler expects it: ours are masked and
 * cleared. */
void kilobot_enter_bootloader(void) {
    cli();
    kilobot_motors_apply(0, 0);
    TIMSK0 = 0;
    TIMSK1 = 0;
    TIFR0 = _BV(OCF0B) | _BV(OCF0A) | _BV(TOV0); /* flags clear when written 1 */
    TIFR1 = _BV(ICF1) | _BV(OCF1B) | _BV(OCF1A) | _BV(TOV1);
    __asm__ __volatile__("jmp %0" ::"i"(BOOTLOADER_ADDRESS)); /* a byte address, to the assembler */
    __builtin_unreachable();
}

/* A jump leaves the peripherals as they were, so first each one the port
 * or a program may use goes back to its power-up state (datasheet reset
 * values: stopped, interrupts masked, flags cleared, pins inputs): the
 * kernel and the devices then start as after a reset, and no interrupt of
 * the old run fires before its driver is ready for it. */
static void peripherals_as_at_power_up(void) {
    TIMSK0 = TIMSK1 = TIMSK2 = 0;
    TCCR0A = TCCR0B = TCCR1A = TCCR1B = TCCR1C = TCCR2A = TCCR2B = ASSR = 0;
    TCNT0 = OCR0A = OCR0B = TCNT2 = OCR2A = OCR2B = 0;
    TCNT1 = OCR1A = OCR1B = ICR1 = 0;
    TIFR0 = TIFR1 = TIFR2 = 0xFF; /* flags clear when written 1 */
    ADCSRA = _BV(ADIF);           /* off, its flag cleared */
    ADCSRB = ADMUX = DIDR0 = DIDR1 = 0;
    ACSR = _BV(ACI);
    /* The serial port's interrupts only: debug_init sets the rest again, and
     * a transmitter disabled mid-byte never shows an empty buffer again in
     * simavr 1.6 (printf would wait for ever). */
    UCSR0B &= (uint8_t) ~(_BV(RXCIE0) | _BV(TXCIE0) | _BV(UDRIE0));
    SPCR = TWCR = 0;
    EIMSK = EICRA = PCICR = PCMSK0 = PCMSK1 = PCMSK2 = 0;
    EIFR = PCIFR = 0xFF;
    SMCR = PRR = 0;
    DDRB = DDRC = DDRD = PORTB = PORTC = PORTD = 0;
}

void kilobot_restart(uint16_t mark) {
    cli();
    peripherals_as_at_power_up();
    restart_mark = mark;
    __asm__ __volatile__("jmp 0");
    __builtin_unreachable();
}

uint16_t kilobot_restart_mark(void) {
    uint16_t mark = restart_mark;
    restart_mark = 0;
    return mark;
}
