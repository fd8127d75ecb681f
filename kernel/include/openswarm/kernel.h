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

/* Ask the system thread to stop scheduling and return from
 * Sys_Run_SystemThread (callable from anywhere, including interrupts). */
void Sys_Stop_Kernel(void);

#ifdef __cplusplus
}
#endif

#endif
