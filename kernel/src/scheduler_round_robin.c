/* Round robin: every ready thread is queued at the tail and runs for one
 * time slice in turn. Nothing preempts before the slice ends. */
#include "openswarm/scheduler.h"

static void insert_at_tail(sys_tcb **head, sys_tcb *t) {
    while (*head != NULL) head = Sys_Tcb_Next(*head);
    *head = t;
}

static bool never_preempts(const sys_tcb *first, const sys_tcb *running) {
    (void)first;
    (void)running;
    return false;
}

const sys_scheduler sys_scheduler_round_robin = {"round-robin", insert_at_tail, never_preempts};
