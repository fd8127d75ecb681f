/* OpenSwarm kernel: include this one header.
 *
 *   int main(void) {
 *       Sys_Init_Kernel();
 *       ... register events, subscribe handlers, start processes ...
 *       Sys_Start_Kernel();
 *       Sys_Run_SystemThread(); // main becomes the system thread
 *   }
 */
#ifndef OPENSWARM_KERNEL_H
#define OPENSWARM_KERNEL_H

#include "openswarm/types.h"
#include "openswarm/process.h"
#include "openswarm/scheduler.h"
#include "openswarm/event.h"
#include "openswarm/system_time.h"
#include "openswarm/hal.h"
#include "openswarm/fault.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Reset every kernel table, initialise the port, register the kernel's own
 * events and make the caller the system thread (pid 0). Calling it again
 * (before Sys_Start_Kernel or after Sys_Run_SystemThread returned) starts
 * from scratch. */
void Sys_Init_Kernel(void);

/* Start the tick and enable interrupts. No thread runs until
 * Sys_Run_SystemThread. */
void Sys_Start_Kernel(void);

/* Turn the caller into the system thread: dispatch events, reap ended
 * threads, run the ready threads and idle the CPU when none is. Returns only
 * after Sys_Stop_Kernel. */
void Sys_Run_SystemThread(void);

/* Turn the caller into the system thread running program, a loop of the
 * app's own on main()'s stack (no thread, no stack of its own): events
 * it sends, and those interrupts send while it runs, are dispatched at
 * once, their handlers nested on its stack; it waits with Sys_Idle, where
 * the system thread reaps, runs the ready threads and idles. If program
 * returns, the caller goes on as Sys_Run_SystemThread. */
void Sys_Run_SystemProgram(void (*program)(void));

/* Whether the caller is that program (not a handler, interrupt or thread). */
bool Sys_In_SystemProgram(void);

/* From the program: the system thread's work, or, if there is none, the
 * ready threads run until none is left, or the CPU sleeps until an
 * interrupt (at most max_ms). Returns after one such turn: the program
 * asks again until what it waits for has come. SYS_E_CONTEXT from
 * anything but the program. */
sys_status Sys_Idle(uint32_t max_ms);

/* Ask the system thread to stop scheduling and return from
 * Sys_Run_SystemThread (callable from anywhere, including interrupts). */
void Sys_Stop_Kernel(void);

#ifdef __cplusplus
}
#endif

#endif
