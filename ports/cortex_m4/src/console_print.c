/* Text on the board's console, without a C library's printf. */
#include "openswarm/cortex_m4.h"

#include <string.h>

void cortex_m4_print(const char *text) { board_console_write(text, (uint32_t)strlen(text)); }

void cortex_m4_print_uint(uint32_t value) {
    char digits[10];
    unsigned n = 0;
    do {
        digits[sizeof digits - 1 - n++] = (char)('0' + value % 10u);
        value /= 10u;
    } while (value != 0);
    board_console_write(&digits[sizeof digits - n], n);
}

void cortex_m4_print_hex(uint32_t value) {
    char digits[8];
    for (unsigned i = 0; i < 8; i++) digits[i] = "0123456789abcdef"[(value >> (28 - 4 * i)) & 0xFu];
    board_console_write(digits, 8);
}
