/* Threads (the paper's processes): creation, termination, yielding,
 * critical sections and the five-state model. */
#ifndef OPENSWARM_PROCESS_H
#define OPENSWARM_PROCESS_H

#include "openswarm/types.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum sys_process_state {
    SYS_PROCESS_NEW = 0,  /* created, has not run yet */
    SYS_PROCESS_READY,    /* waiting for the CPU */
    SYS_PROCESS_RUNNING,  /* on the CPU */
    SYS_PROCESS_BLOCKED,  /* waiting for an event or a timeout */
    SYS_PROCESS_ZOMBIE    /* terminated, not yet reaped */
} sys_process_state;

typedef void (*sys_process_fn)(void *arg);

#define SYS_PRIORITY_DEFAULT 0

/* Start a thread running fn() on a stack of OS_CFG_DEFAULT_STACK_BYTES.
 * Returns its pid, or SYS_PID_NONE if a pool is full (see Sys_Get_Stats). */
sys_pid Sys_Start_Process(void (*fn)(void));

/* Start a thread running fn(arg) with an explicit stack size (0 = default)
 * and priority (used by priority schedulers; higher runs first). */
sys_status Sys_Start_Process_Ex(sys_process_fn fn, void *arg, uint16_t stack_bytes,
                                uint8_t priority, sys_pid *pid);

/* Terminate a thread. Its subscriptions are removed, a wait it was blocked
 * in is abandoned, and its stack and slot are reaped by the system thread.
 * A thread may kill itself (this call then does not return). */
sys_status Sys_Kill_Process(sys_pid pid);

/* Give the CPU to the next ready thread; returns at once if none is ready. */
sys_status Sys_Yield(void);

/* Critical sections postpone every thread switch and event dispatch until
 * the outermost Sys_End_CriticalSection. Interrupts stay enabled. They nest;
 * a thread that ends while inside one releases it (counted as a leak).
 * Interrupts cannot open one (SYS_E_CONTEXT): they already run to the end. */
sys_status Sys_Start_CriticalSection(void);
sys_status Sys_End_CriticalSection(void);

sys_pid Sys_Get_ProcessID(void);
/* SYS_E_INVALID for an unknown or reaped pid, else SYS_OK and *state. */
sys_status Sys_Get_ProcessState(sys_pid pid, sys_process_state *state);
sys_status Sys_Set_Priority(sys_pid pid, uint8_t priority);

/* Number of thread-to-thread switches since Sys_Init_Kernel. */
uint32_t Sys_Get_SwitchCount(void);

#ifdef __cplusplus
}
#endif

#endif
