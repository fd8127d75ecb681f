/* Scheduling policies. A policy decides where a ready thread is queued and
 * when the first ready thread preempts the running one; the kernel does the
 * rest (time slices, blocking, switching). Replaceable at run time. */
#ifndef OPENSWARM_SCHEDULER_H
#define OPENSWARM_SCHEDULER_H

#include "openswarm/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A thread control block; policies see it only through the accessors. */
typedef struct sys_tcb sys_tcb;

typedef struct sys_scheduler {
    const char *name;
    /* Insert t into the ready list *head. */
    void (*insert)(sys_tcb **head, sys_tcb *t);
    /* True if first (head of the ready list) must take the CPU from running
     * now rather than at the end of running's time slice. */
    bool (*preempts)(const sys_tcb *first, const sys_tcb *running);
} sys_scheduler;

/* What a policy may use: a thread's priority and its ready-list link. */
uint8_t Sys_Tcb_Priority(const sys_tcb *t);
sys_tcb **Sys_Tcb_Next(sys_tcb *t);

/* Round robin: FIFO, every thread gets its slice in turn (the default). */
extern const sys_scheduler sys_scheduler_round_robin;
/* Fixed priority, preemptive; round robin among equal priorities. */
extern const sys_scheduler sys_scheduler_priority;

/* Switch policy; the ready threads are re-queued under the new one. */
sys_status Sys_Set_Scheduler(const sys_scheduler *scheduler);
const sys_scheduler *Sys_Get_Scheduler(void);

/* Time slice in ms (>= 1). */
sys_status Sys_Set_TimeSlice(uint16_t ms);

#ifdef __cplusplus
}
#endif

#endif
