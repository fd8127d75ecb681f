/* Short texts to the board's console, for fault reports. */
#ifndef CORTEX_M4_TEXT_OUT_H
#define CORTEX_M4_TEXT_OUT_H

#include <stdint.h>

void text_out(const char *text);
void text_out_uint(uint32_t value);
void text_out_hex(uint32_t value);

#endif
