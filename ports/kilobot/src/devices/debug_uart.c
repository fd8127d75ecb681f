/* The debug serial port: USART0 transmitter, 38400 baud from 8 MHz with
 * double speed (UBRR 25: 38462 baud, 0.2 % off), as stdout: printf after
 * kilobot_console_init() (robot_console_init() in robot.h; kilolib
 * programs call it debug_init(), as the classic library's debug.h). */
#include <avr/io.h>
#include <stdio.h>

#include "debug.h"
#include "openswarm/kilobot.h"

static int uart_putchar(char c, FILE *stream) {
    (void)stream;
    if (c == '\n') uart_putchar('\r', stream);
    while (!(UCSR0A & _BV(UDRE0))) {
    }
    UDR0 = (uint8_t)c;
    return 0;
}

static FILE uart_stdout = FDEV_SETUP_STREAM(uart_putchar, NULL, _FDEV_SETUP_WRITE);

void kilobot_console_init(void) {
    UBRR0 = 25;
    UCSR0A = _BV(U2X0);
    UCSR0B = _BV(TXEN0);
    UCSR0C = _BV(UCSZ01) | _BV(UCSZ00);
    stdout = &uart_stdout;
}

void debug_init(void) { kilobot_console_init(); }
