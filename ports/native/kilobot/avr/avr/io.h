/* The ATmega328P's I/O registers in the native mode: a register file of
 * the robot's own (in its RAM image), at the data-space addresses the
 * datasheet gives. Code that writes and reads them keeps working; the board
 * looks at the ones that drive something (the LED's and motors' pins and
 * PWM) when interrupts come back on, and sets the ones that read something
 * (the charger's pin). Timers and peripherals do not run: a program that
 * programs them itself runs in the exact mode only. */
#ifndef OPENSWARM_NATIVE_AVR_IO_H
#define OPENSWARM_NATIVE_AVR_IO_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

extern volatile uint8_t native_avr_io[0x100];

#ifdef __cplusplus
}
#endif

#define _SFR_MEM8(a) (native_avr_io[(a)])
#define _SFR_MEM16(a) (*(volatile uint16_t *)&native_avr_io[(a)])
#define _BV(bit) (1u << (bit))
#define bit_is_set(r, bit) ((r) & _BV(bit))
#define bit_is_clear(r, bit) (!((r) & _BV(bit)))

#define PINB _SFR_MEM8(0x23)
#define DDRB _SFR_MEM8(0x24)
#define PORTB _SFR_MEM8(0x25)
#define PINC _SFR_MEM8(0x26)
#define DDRC _SFR_MEM8(0x27)
#define PORTC _SFR_MEM8(0x28)
#define PIND _SFR_MEM8(0x29)
#define DDRD _SFR_MEM8(0x2A)
#define PORTD _SFR_MEM8(0x2B)
#define TIFR0 _SFR_MEM8(0x35)
#define TIFR1 _SFR_MEM8(0x36)
#define TIFR2 _SFR_MEM8(0x37)
#define PCIFR _SFR_MEM8(0x3B)
#define EIFR _SFR_MEM8(0x3C)
#define EIMSK _SFR_MEM8(0x3D)
#define GPIOR0 _SFR_MEM8(0x3E)
#define TCCR0A _SFR_MEM8(0x44)
#define TCCR0B _SFR_MEM8(0x45)
#define TCNT0 _SFR_MEM8(0x46)
#define OCR0A _SFR_MEM8(0x47)
#define OCR0B _SFR_MEM8(0x48)
#define GPIOR1 _SFR_MEM8(0x4A)
#define GPIOR2 _SFR_MEM8(0x4B)
#define SPCR _SFR_MEM8(0x4C)
#define ACSR _SFR_MEM8(0x50)
#define SMCR _SFR_MEM8(0x53)
#define MCUSR _SFR_MEM8(0x54)
#define MCUCR _SFR_MEM8(0x55)
#define WDTCSR _SFR_MEM8(0x60)
#define CLKPR _SFR_MEM8(0x61)
#define PRR _SFR_MEM8(0x64)
#define OSCCAL _SFR_MEM8(0x66)
#define PCICR _SFR_MEM8(0x68)
#define EICRA _SFR_MEM8(0x69)
#define PCMSK0 _SFR_MEM8(0x6B)
#define PCMSK1 _SFR_MEM8(0x6C)
#define PCMSK2 _SFR_MEM8(0x6D)
#define TIMSK0 _SFR_MEM8(0x6E)
#define TIMSK1 _SFR_MEM8(0x6F)
#define TIMSK2 _SFR_MEM8(0x70)
#define ADCW _SFR_MEM16(0x78)
#define ADCSRA _SFR_MEM8(0x7A)
#define ADCSRB _SFR_MEM8(0x7B)
#define ADMUX _SFR_MEM8(0x7C)
#define DIDR0 _SFR_MEM8(0x7E)
#define DIDR1 _SFR_MEM8(0x7F)
#define TCCR1A _SFR_MEM8(0x80)
#define TCCR1B _SFR_MEM8(0x81)
#define TCCR1C _SFR_MEM8(0x82)
#define TCNT1 _SFR_MEM16(0x84)
#define ICR1 _SFR_MEM16(0x86)
#define OCR1A _SFR_MEM16(0x88)
#define OCR1B _SFR_MEM16(0x8A)
#define TCCR2A _SFR_MEM8(0xB0)
#define TCCR2B _SFR_MEM8(0xB1)
#define TCNT2 _SFR_MEM8(0xB2)
#define OCR2A _SFR_MEM8(0xB3)
#define OCR2B _SFR_MEM8(0xB4)
#define ASSR _SFR_MEM8(0xB6)
#define TWCR _SFR_MEM8(0xBC)
#define UCSR0A _SFR_MEM8(0xC0)
#define UCSR0B _SFR_MEM8(0xC1)
#define UCSR0C _SFR_MEM8(0xC2)
#define UBRR0 _SFR_MEM16(0xC4)
#define UDR0 _SFR_MEM8(0xC6)

/* Pins */
#define PB0 0
#define PB1 1
#define PB2 2
#define PB3 3
#define PB4 4
#define PB5 5
#define PB6 6
#define PB7 7
#define PC0 0
#define PC1 1
#define PC2 2
#define PC3 3
#define PC4 4
#define PC5 5
#define PC6 6
#define PD0 0
#define PD1 1
#define PD2 2
#define PD3 3
#define PD4 4
#define PD5 5
#define PD6 6
#define PD7 7

/* Timer2 (the motors' PWM) and the bits the board's code names */
#define WGM20 0
#define WGM21 1
#define COM2B0 4
#define COM2B1 5
#define COM2A0 6
#define COM2A1 7
#define CS20 0
#define CS21 1
#define CS22 2
#define WGM01 1
#define CS00 0
#define CS01 1
#define CS02 2
#define OCIE0A 1
#define OCF0A 1
#define ADSC 6
#define ADEN 7
#define ADIF 4
#define ACI 4
#define SE 0
#define U2X0 1
#define UDRE0 5
#define TXEN0 3
#define UCSZ00 1
#define UCSZ01 2

#endif
