/* Driving the host port: the kernel runs on a simulated CPU (one POSIX
 * thread) and the caller plays the hardware around it, delivering ticks and
 * interrupts. With HOST_CLOCK_MANUAL nothing happens unless the caller says
 * so, which makes tests deterministic; with HOST_CLOCK_REALTIME a timer
 * ticks every millisecond of wall-clock time. Ticks and interrupts preempt
 * whatever thread runs, even one that spins forever. */
#ifndef OPENSWARM_HOST_H
#define OPENSWARM_HOST_H

#include <stdbool.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum host_clock { HOST_CLOCK_REALTIME = 0, HOST_CLOCK_MANUAL } host_clock;

/* Clock used by the next Sys_Start_Kernel (default: real time). */
void host_set_clock(host_clock clock);

/* Power on a CPU thread that runs Sys_Init_Kernel(), setup(),
 * Sys_Start_Kernel() and Sys_Run_SystemThread(). */
void host_cpu_start(host_clock clock, void (*setup)(void));

/* Power on a CPU thread that runs an app's main, which initialises and
 * starts the kernel itself (Sys_Init_Kernel ... Sys_Run_SystemThread);
 * returns once the kernel runs its threads, like host_cpu_start. */
void host_cpu_start_main(host_clock clock, int (*app_main)(void));

/* Stop the kernel (Sys_Stop_Kernel from an interrupt) and join the CPU. */
void host_cpu_stop(void);

/* Manual clock: deliver ms ticks, one at a time; each is delivered once the
 * previous one was serviced and the CPU is back in a thread or idle (plus a
 * moment of wall-clock time for the threads to run). */
void host_cpu_advance(uint32_t ms);

/* Run isr(arg) as an interrupt on the CPU and wait until it was serviced. */
void host_cpu_interrupt(void (*isr)(void *), void *arg);

/* Wait until every thread is blocked and nothing is pending: false if that
 * did not happen within timeout_ms of wall-clock time. */
bool host_cpu_wait_idle(uint32_t timeout_ms);

/* For the port's own tests only: hook(), when not NULL, runs on the idle
 * CPU between its look for pending interrupts and its acknowledgement of
 * those raised, the window where a raise must not be acknowledged before
 * it was serviced (tests/host/test_host_port.cpp widens it with a sleep).
 * Set it while the CPU is off (before host_cpu_start, after host_cpu_stop). */
void host_cpu_set_idle_window_hook(void (*hook)(void));

#ifdef __cplusplus
}
#endif

#endif
