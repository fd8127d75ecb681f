/* The console on UART1, which carries the e-puck's Bluetooth link
 * (LMX9820A at 115200 baud; e-puck library, e_uart_char): polled, so it
 * works from a trap and with interrupts masked, and costs no buffer. */
#include "dspic_port.h"
#include "p30f6014a_registers.h"

/* 14.7456 MHz / (16 x 115200) = 8 exactly: U1BRG = 8 - 1, no error. */
#define BAUD 115200ul
#define U1BRG_VALUE ((uint16_t)(DSPIC_FCY_HZ / (16u * BAUD) - 1u))

void dspic_console_init(void) {
    U1BRG = U1BRG_VALUE;
    U1MODE = UMODE_UARTEN;
    U1STA = USTA_UTXEN;
}

static void put(char c) {
    while (U1STA & USTA_UTXBF) {
        /* the 4-character FIFO is full */
    }
    U1TXREG = (uint8_t)c;
}

void dspic_console_put(char c) {
    if (c == '\n') put('\r'); /* a terminal's new line */
    put(c);
}

void dspic_console_print(const char *text) {
    for (; *text != '\0'; text++) dspic_console_put(*text);
}

void dspic_console_print_hex(uint16_t value) {
    static const char digits[] = "0123456789abcdef";
    for (int shift = 12; shift >= 0; shift -= 4) put(digits[(value >> shift) & 0xFu]);
}

void dspic_console_print_uint(uint16_t value) {
    char text[6];
    unsigned i = sizeof text - 1u;
    text[i] = '\0';
    do {
        text[--i] = (char)('0' + value % 10u);
        value /= 10u;
    } while (value != 0);
    dspic_console_print(&text[i]);
}
