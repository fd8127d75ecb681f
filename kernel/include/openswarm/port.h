/*
 * The port interface: everything the portable kernel needs from a CPU and
 * board, and the kernel entry points a port calls. Nothing else crosses
 * between kernel/ and ports/. Each port supplies "openswarm/port_arch.h"
 * with the types and constants below.
 *
 * Interrupt model. The kernel runs its own bookkeeping with interrupts
 * masked (port_irq_save/restore). An interrupt service routine that may
 * call Sys_* functions is bracketed by os_isr_enter() and os_isr_exit();
 * os_isr_exit() may switch threads (through port_switch) before the
 * interrupted context is resumed, exactly like a voluntary switch, so the
 * ISR prologue must have saved every register the switch does not.
 */
#ifndef OPENSWARM_PORT_H
#define OPENSWARM_PORT_H

#include "openswarm/types.h"
#include "openswarm/port_arch.h"

/*
 * port_arch.h provides:
 *   port_context_t      per-thread saved CPU state (e.g. the stack pointer)
 *   port_irq_state_t    what port_irq_save returns
 *   PORT_STACK_EXTRA    bytes the port adds to every requested stack
 *                       (0 on robots; room for libc and signals on a host)
 *   PORT_STACK_ALIGN    alignment of stack blocks (a power of two)
 */

#ifdef __cplusplus
extern "C" {
#endif

/* ---- provided by the port ---- */

/* Prepare the CPU, the tick timer (not started) and the interrupt vector.
 * Called by Sys_Init_Kernel; must make the caller's context the one that
 * port_switch saves into the system thread's context. */
void port_init(void);

/* Prepare ctx so that the first port_switch to it calls entry(arg) on the
 * stack [stack, stack + size) with interrupts enabled; if entry returns,
 * the port calls os_thread_exit(). */
void port_context_init(port_context_t *ctx, void *stack, size_t size, void (*entry)(void *),
                       void *arg);

/* Save the running context into from and resume to. Called with interrupts
 * masked; returns (interrupts still masked) when from is resumed. */
void port_switch(port_context_t *from, port_context_t *to);

/* Call fn on the stack of the suspended system thread (system is its saved
 * context), from a thread or at the end of an interrupt, interrupts masked;
 * fn returns with interrupts masked. Event handlers run this way as soon as
 * an event is sent, without two full thread switches, and without using the
 * stack of the thread they interrupted. */
void port_call_on_system_stack(port_context_t *system, void (*fn)(void));

/* Start the periodic 1 ms tick; its ISR calls os_tick(). */
void port_tick_start(void);

/* Mask interrupts and return the previous mask state / restore it. */
port_irq_state_t port_irq_save(void);
void port_irq_restore(port_irq_state_t state);
/* Unmask / mask unconditionally. */
void port_irq_enable(void);
void port_irq_disable(void);

/* Called by the system thread, interrupts masked, when nothing can run:
 * wait for an interrupt (e.g. SLEEP), let it be serviced, and return with
 * interrupts masked again. */
void port_idle(void);

/* Tickless idle (OS_CFG_TICKLESS; a port that has it defines
 * PORT_TICKLESS_IDLE in port_arch.h). Called by the system thread instead
 * of port_idle, as port_idle is, with the number of ticks from now until
 * the first one the kernel needs (1: the next; UINT32_MAX: none). The port
 * may stop the tick meanwhile; ticks that pass while it is stopped are
 * credited with os_ticks_slept before the kernel runs again: before this
 * returns, and in port_tickless_wake when an interrupt comes first. */
void port_idle_for(uint32_t ticks);

/* Called first by os_isr_enter (OS_CFG_TICKLESS): if the tick is stopped,
 * credit the ticks that passed (os_ticks_slept) and restart it, so the
 * interrupt's handler sees the exact time. Every interrupt that calls the
 * kernel pays its test: keep it short. */
void port_tickless_wake(void);

/* A fault the kernel detected (a sys_fault, and the thread's pid), before
 * the application's hook and SYS_EVENT_FAULT: the port tells whoever
 * watches (a simulator's console, a terminal), so no fault goes unseen.
 * Interrupts are masked; keep it short. */
void port_report_fault(uint8_t fault, sys_pid pid);

/* ---- provided by the kernel, called by the port ---- */

void os_isr_enter(void);
/* May switch threads; returns when the interrupted context runs again. */
void os_isr_exit(void);
/* One 1 ms tick; call between os_isr_enter and os_isr_exit. */
void os_tick(void);
/* The 1 ms tick, if it needs nothing but the time and the slice's count
 * (most do), or ends the slice of a thread that then only makes way for
 * the next ready one: it is counted (and that switch made, with
 * port_switch, when no interrupt is nested: so may this return in another
 * thread's time, as os_isr_exit does) and true is returned, and the
 * interrupt needs neither os_isr_enter nor os_isr_exit. Otherwise nothing
 * is done and false returned: call os_isr_enter, os_tick and os_isr_exit.
 * Interrupts masked. A port that cannot switch where its tick runs (the
 * Cortex-M4's, which switches in thread mode only) calls os_tick alone. */
bool os_tick_quiet(void);
/* ticks that passed while the tick was stopped by port_idle_for, credited
 * at once (interrupts masked, the system thread idle): the time advances
 * by ticks and waits whose deadline came meanwhile end. A port that sleeps
 * longer than 65535 ticks wakes and credits them in parts. */
void os_ticks_slept(uint16_t ticks);
#ifdef PORT_STACK_POOL
/* The bytes the port's stack pool (PORT_STACK_POOL) must hold, aligned to
 * PORT_STACK_ALIGN: the configuration's stacks and the port's extra. */
extern const size_t os_stack_pool_bytes;
#endif
/* End the running thread (its entry function returned). Never returns. */
void os_thread_exit(void);
/* End the running thread because the CPU trapped in it (the port's fault
 * handler resumed it here): fault is reported as any kernel fault and
 * counted. Never returns. */
void os_thread_fault(uint8_t fault);

#ifdef __cplusplus
}
#endif

#endif
