/* What only Microchip XC16 understands, in one place: interrupt handlers
 * and the dsPIC's instructions. Built by XC16 each macro has its real
 * meaning; for the host's syntax check (DSPIC_SYNTAX_CHECK, a 16-bit
 * compiler that is not XC16: tests/dspic) a stand-in with the same type,
 * so the check covers everything else. */
#ifndef DSPIC_COMPILER_H
#define DSPIC_COMPILER_H

#include <stdint.h>

#if defined(__XC16__)
/* An interrupt or trap handler, named as XC16's vector table names them
 * (_T1Interrupt, _StackError, ...). no_auto_psv: the handlers read no
 * constants through the program-space window, so PSVPAG is left alone. */
#define DSPIC_ISR(name) void __attribute__((interrupt, no_auto_psv)) name(void)
/* PWRSAV #1: Idle mode; the CPU stops, peripherals run; an enabled
 * interrupt wakes it whatever the CPU priority (DS70046, Watchdog Timer
 * and Power-Saving Modes). */
#define DSPIC_IDLE() __asm__ __volatile__("pwrsav #1" ::: "memory")
#define DSPIC_NOP() __builtin_nop()
/* TBLRDL: the low word of program memory (or the data EEPROM, which the
 * table instructions reach from page 0x7F) at offset in page TBLPAG. */
#define DSPIC_TABLE_READ_LOW(offset) ((uint16_t)__builtin_tblrdl(offset))
#elif defined(DSPIC_SYNTAX_CHECK)
#define DSPIC_ISR(name) void name(void)
#define DSPIC_IDLE() __asm__ __volatile__("" ::: "memory")
#define DSPIC_NOP() __asm__ __volatile__("" ::: "memory")
uint16_t dspic_table_read_low_stand_in(uint16_t offset);
#define DSPIC_TABLE_READ_LOW(offset) dspic_table_read_low_stand_in(offset)
#else
#error "the e-puck's dsPIC port builds with Microchip XC16 (xc16-gcc), or with DSPIC_SYNTAX_CHECK for the host's check"
#endif

/* Neither compiler may move memory accesses across it: the kernel's
 * data, written inside a critical section, is not volatile. */
#define DSPIC_BARRIER() __asm__ __volatile__("" ::: "memory")

#endif
