/* The e-puck2's console: USART3 (TX PD8, RX PD9), 115200 baud 8N1, the
 * serial line GCtronic's firmware opens (src/serial_comm.c, sdStart(&SD3,
 * 115200)); it reaches a computer through the ESP32's Bluetooth serial
 * link. Text goes into a buffer that the transmitter empties on its TXE
 * interrupt, so a print does not wait for the line. */
#ifndef EPUCK2_CONSOLE_USART_H
#define EPUCK2_CONSOLE_USART_H

#include <stdint.h>

#define EPUCK2_CONSOLE_BAUD 115200u
#define EPUCK2_CONSOLE_BUFFER_BYTES 256u
/* A byte takes 87 us at 115200 baud; a writer facing a full buffer sends
 * the oldest byte itself, waiting for TXE at most this many reads (about
 * a millisecond at 168 MHz), after which the transmitter is taken as dead
 * and the byte is dropped and counted. */
#define EPUCK2_CONSOLE_TXE_POLLS 40000u

/* The USART's clock is APB1 (42 MHz with the clock tree running, 16 MHz
 * if it did not start): BRR = apb1_hz / baud, rounded (RM0090 30.6.3,
 * oversampling by 16: mantissa and fraction in sixteenths together). */
void epuck2_console_init(uint32_t apb1_hz);

/* Queues the bytes. Blocks while the buffer is full (sending bytes itself,
 * so it works with interrupts masked too); never loses a byte unless the
 * transmitter stops (epuck2_console_lost). Not reentrant: callers on
 * several threads serialise it (the board masks interrupts around it). */
void epuck2_console_write(const char *text, uint32_t length);

/* Sends what is buffered, waiting for the transmitter (for a board about
 * to halt). */
void epuck2_console_flush(void);

/* Bytes dropped because the transmitter never became ready; times a
 * writer found the buffer full. */
uint32_t epuck2_console_lost(void);
uint32_t epuck2_console_full_waits(void);

void USART3_IRQHandler(void);

#endif
