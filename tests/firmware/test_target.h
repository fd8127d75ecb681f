/* What a firmware test suite needs from the robot it runs on: text out,
 * an interrupt on demand, and an exit status. One implementation per
 * target: tests/avr/test_target_avr.c (the Kilobot under openswarm-sim),
 * tests/qemu/test_target_cm4.c (the e-puck2 image under QEMU). */
#ifndef TEST_TARGET_H
#define TEST_TARGET_H

#include <stdint.h>

#ifdef __AVR__
#include <avr/pgmspace.h>
#define TEXT(literal) PSTR(literal) /* in flash: 2 KB of RAM has no room for text */
#else
#define TEXT(literal) (literal)
#endif

/* First thing in main. */
void target_init(void);

/* text: a TEXT() literal. */
void target_puts(const char *text);
void target_putc(char c);
void target_put_uint(uint32_t value);

/* About us microseconds from now, an interrupt handler (bracketed for
 * the kernel) calls target_interrupt(value), which the suite defines. */
void target_interrupt_in(uint16_t us, int16_t value);
void target_interrupt(int16_t value);

void target_exit(uint8_t status) __attribute__((noreturn));

#endif
