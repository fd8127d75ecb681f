/* Fixed priority: the ready list is ordered by priority, highest first; a
 * thread is queued behind those of equal priority, so equals share the CPU
 * round robin. A ready thread of higher priority preempts at once. */
#include "openswarm/scheduler.h"

static void insert_by_priority(sys_tcb **head, sys_tcb *t) {
    uint8_t p = Sys_Tcb_Priority(t);
    while (*head != NULL && Sys_Tcb_Priority(*head) >= p) head = Sys_Tcb_Next(*head);
    *Sys_Tcb_Next(t) = *head;
    *head = t;
}

static bool higher_priority(const sys_tcb *first, const sys_tcb *running) {
    return Sys_Tcb_Priority(first) > Sys_Tcb_Priority(running);
}

const sys_scheduler sys_scheduler_priority = {"priority", insert_by_priority, higher_priority};
