/* Cortex-M4 port: what boards and device drivers use. The kernel sees
 * only openswarm/port.h.
 *
 * Interrupt priorities (4 bits, as on the STM32F4; lower is more urgent):
 *   0x00       SVC (the interrupt epilogue's return; never masked)
 *   0x10       interrupts that never call the kernel: not masked by
 *              critical sections, so their latency is the hardware's
 *   0x20-0xE0  interrupts that call the kernel (Sys_Send_Event,
 *              Sys_Device_Input, ...): masked by the kernel
 *   0xE0       SysTick, the 1 ms tick
 *   0xF0       PendSV, the epilogue that runs the kernel's decision
 *
 * A kernel-aware interrupt handler is bracketed like this:
 *
 *     void TIM3_IRQHandler(void) {
 *         cortex_m4_isr_enter();
 *         ... Sys_Device_Input(...) ...
 *         cortex_m4_isr_exit();
 *     }
 */
#ifndef OPENSWARM_CORTEX_M4_H
#define OPENSWARM_CORTEX_M4_H

#include <stdbool.h>
#include <stdint.h>

#include "openswarm/types.h"

#ifdef __cplusplus
extern "C" {
#endif

#define CORTEX_M4_PRIORITY_UNMASKED 0x10u
#define CORTEX_M4_PRIORITY_KERNEL 0x20u /* the most urgent kernel-aware level */
#define CORTEX_M4_PRIORITY_DEVICE 0x80u /* a sensible default for devices */

/* Around a kernel-aware interrupt handler's body. The kernel's decision
 * (switch threads, run event handlers) is taken after the last nested
 * handler ends, in thread mode (see README: the epilogue). */
void cortex_m4_isr_enter(void);
void cortex_m4_isr_exit(void);

/* Set an interrupt's (irq >= 0) priority and enable it in the NVIC. */
void cortex_m4_irq_enable(int irq, uint8_t priority);
void cortex_m4_irq_disable(int irq);

/* Work the board adds to the 1 ms tick (in the tick interrupt, after the
 * kernel's). NULL for none. With tickless idle (OS_CFG_TICKLESS) the CPU
 * sleeps through ticks without their interrupt: the hook runs at every
 * tick that interrupts, and certainly at the tick when the kernel's time
 * reaches cortex_m4_tick_hook_ms (the board keeps it up to date; a time
 * past: every tick). */
extern void (*cortex_m4_tick_hook)(void);
extern uint32_t cortex_m4_tick_hook_ms;

/* Called by the idle thread with interrupts held (PRIMASK) just before it
 * sleeps (asleep true) and just after it wakes, before the interrupt that
 * woke it is taken (false): a board that accounts for the CPU's time
 * (the world board under QEMU) sees the sleep alone. NULL for none. */
extern void (*cortex_m4_idle_hook)(bool asleep);

/* Text on the board's console (fault reports, records): a string, a
 * number in decimal, a word in hexadecimal (8 digits). */
void cortex_m4_print(const char *text);
void cortex_m4_print_uint(uint32_t value);
void cortex_m4_print_hex(uint32_t value);

/* ---- supplied by the board ---- */

/* SysTick's clock (the core clock) in Hz once board_init has run. */
extern const uint32_t board_core_hz;

/* Called by the reset handler before main, with .data and .bss ready and
 * the FPU on: clocks, the console. */
void board_init(void);

/* Text for a person (fault reports): the board's console. */
void board_console_write(const char *text, uint32_t length);

/* Nothing can go on (a CPU fault outside any thread, in an interrupt or
 * the system thread): the board stops (an emulator exits with status,
 * a robot halts showing it). Never returns. */
void board_halt(int status) __attribute__((noreturn));

#ifdef __cplusplus
}
#endif

#endif
