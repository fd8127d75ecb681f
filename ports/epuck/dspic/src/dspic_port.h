/* What the dsPIC port's files share: the clock, interrupt priorities, the
 * kernel-aware interrupt wrapper, the console and the stop. */
#ifndef DSPIC_PORT_H
#define DSPIC_PORT_H

#include <stdbool.h>
#include <stdint.h>

#include "openswarm/port.h"

/* Instruction clock: the e-puck's 7.3728 MHz crystal x PLL 8 / 4
 * (e_epuck_ports.h: FOSC, PLL, FCY). */
#define DSPIC_FCY_HZ 14745600ul

/* Interrupt priorities (1..7; 7 is the kernel's mask). Those that call
 * the kernel share one, so none nests in another; the steppers, which
 * never call it, come first so a step is not delayed by a tick. */
#define DSPIC_PRIORITY_KERNEL 3u
#define DSPIC_PRIORITY_STEPPERS 5u
/* The camera's VSYNC and line interrupts: a line is read by counting
 * cycles from HREF, so they come before everything else (never the
 * kernel: a frame is handed on through the kernel-level Timer3 flag). */
#define DSPIC_PRIORITY_CAMERA 6u

/* Bytes above SPLIM a stack-error trap may stack into (its 2-word frame,
 * rounded up): port_context_init leaves them free. */
#define DSPIC_TRAP_ROOM_BYTES 8u

/* The running context (port_switch and port_call_on_system_stack keep it),
 * for the traps; NULL until the first switch. */
extern port_context_t *volatile dspic_running;

/* Run body as a kernel-aware interrupt's: masked, between os_isr_enter and
 * os_isr_exit (which may switch threads). */
void dspic_isr_run(void (*body)(void));

/* Called from the tick interrupt after os_tick, inside dspic_isr_run. */
extern void (*dspic_tick_hook)(void);

/* The console: UART1, the e-puck's Bluetooth link, polled. */
void dspic_console_init(void);
void dspic_console_put(char c); /* a new line as CR LF */
void dspic_console_print(const char *text);
void dspic_console_print_hex(uint16_t value);
void dspic_console_print_uint(uint16_t value);

/* Stop the robot for good after a fault outside any thread. */
void dspic_stop(void) __attribute__((noreturn));

#endif
