/* The scheduling mechanism: the ready list, time slices and the decision
 * of who runs next. Where a thread is queued is the policy's business
 * (scheduler_round_robin.c, scheduler_priority.c).
 *
 * The system thread (pid 0) is not in the ready list: it runs when nothing
 * else can (it idles the CPU) and when it has work a thread cannot do for
 * it (zombies to reap, a stop). Events sent while a user thread runs are
 * dispatched at once on the system thread's stack, without a switch. A
 * thread preempted by the system thread's work is remembered in
 * os.preempted and resumed with the rest of its slice. */
#include "kernel_internal.h"

uint8_t Sys_Tcb_Priority(const sys_tcb *t) { return t->priority; }
sys_tcb **Sys_Tcb_Next(sys_tcb *t) { return &t->next; }

void os_scheduler_reset(void) {
    os.policy = &sys_scheduler_round_robin;
    os.ready = NULL;
    os.preempted = NULL;
    os.slice_ms = OS_CFG_TIME_SLICE_MS;
    os.slice_left = 0; /* nobody holds a slice: the first thread popped gets one */
}

/* t (its next NULL) joins the ready list where the policy says. Round
 * robin (the default) queues it after os.ready_tail, in the same few
 * cycles however many threads are ready, without its policy's walk. */
static OS_HOT void ready_insert(sys_tcb *t) {
    if (os.policy != &sys_scheduler_round_robin) {
        os.policy->insert(&os.ready, t);
        if (t->next != NULL) return;
    } else if (os.ready == NULL) {
        os.ready = t;
    } else {
        os.ready_tail->next = t;
    }
    os.ready_tail = t;
}

void os_make_ready(sys_tcb *t) {
    if (t->state != SYS_PROCESS_NEW) t->state = SYS_PROCESS_READY;
    t->next = NULL;
    ready_insert(t);
    os.reconsider = true;
}

void os_ready_remove(sys_tcb *t) {
    sys_tcb *prev = NULL;
    for (sys_tcb **link = &os.ready; *link != NULL; link = &(*link)->next) {
        if (*link == t) {
            *link = t->next;
            if (os.ready_tail == t) os.ready_tail = prev; /* NULL: the list is empty */
            t->next = NULL;
            return;
        }
        prev = *link;
    }
}

/* The head leaves the ready list; its stale next is cleared when it is
 * queued again (os_make_ready). os.ready_tail is left as it is: read only
 * while the list is not empty. */
static OS_HOT sys_tcb *ready_pop(void) {
    sys_tcb *t = os.ready;
    if (t != NULL) {
        os.ready = t->next;
        os.slice_left = os.slice_ms; /* a fresh turn */
    }
    return t;
}

/* Should the running (or preempted) thread t give up the CPU to the ready
 * list's head? */
static inline bool must_rotate(const sys_tcb *t) {
    if (os.ready == NULL) {
        if (os.slice_left == 0) os.slice_left = os.slice_ms; /* nobody is waiting: renew it */
        return false;
    }
    return os.slice_left == 0 || os.yield_requested || os.policy->preempts(os.ready, t);
}

/* One more switch: the count's bytes are added to one at a time, as far
 * as the carry goes - on an 8-bit CPU a third of the code of a 32-bit
 * increment, and faster but once in 256 switches. */
static OS_HOT void count_switch(void) {
    for (uint8_t *b = os.switches; ++*b == 0 && b != &os.switches[sizeof os.switches - 1]; b++) {
    }
}

static OS_HOT void switch_to(sys_tcb *next) {
    sys_tcb *prev = os.current;
    os.yield_requested = false; /* a yield is consumed by the switch it caused */
    count_switch();
    os.current = next;
    port_switch(&prev->ctx, &next->ctx);
}

/* The one scheduling decision, for a running thread and for one that
 * stops running (blocks, ends, or is the system thread with no work left):
 * the candidate to run on is the running thread, or else the one the
 * system thread's work preempted. It reads os.current afresh after the
 * dispatch rather than keeping it across: no register to save on the way
 * to the handlers. */
bool os_decide(void) {
    sys_tcb *cand;
    if (os.current->state == SYS_PROCESS_RUNNING) {
        if (os.lock_depth != 0) return false; /* postponed: ended by a decision */
        /* Events first, on the system stack; a handler may kill the thread. */
        if (!os_event_queue_empty()) os_dispatch_on_system_stack();
        cand = os.current->state == SYS_PROCESS_RUNNING ? os.current : NULL;
    } else {
        cand = os.preempted; /* NULL unless the system thread asks */
        os.preempted = NULL;
    }
    os.reconsider = false; /* this decision sees every change */
    sys_tcb *next;
    if (os_system_work_pending()) { /* cand resumes once the work is done */
        if (cand != NULL) cand->state = SYS_PROCESS_READY;
        os.preempted = cand;
        next = OS_SYSTEM;
    } else if (cand != NULL && !must_rotate(cand)) {
        next = cand;
    } else {
        if (cand != NULL) os_make_ready(cand);
        next = ready_pop(); /* cand again if it still comes first */
        if (next == NULL) next = OS_SYSTEM;
    }
    next->state = SYS_PROCESS_RUNNING; /* again, if it was cand or the system thread */
    if (next == os.current) return false;
    switch_to(next);
    return true;
}

/* With a single thread slot only the system thread runs: the decisions
 * below are never taken (and the linker drops them). */
#define OS_THREADS_RUN (OS_CFG_MAX_THREADS > 1)

void os_schedule(void) {
    sys_tcb *cur = os.current;
    if (os.isr_depth != 0) return; /* the interrupt's end decides */
    if (!OS_THREADS_RUN || cur == OS_SYSTEM) {
        os_program_preempted(); /* the system loop decides, unless its program runs */
        return;
    }
    os_check_stack(cur);                               /* before it runs on or blocks */
    os_decide();
}

/* Round robin's rotation in one step: the head leaves the ready list and
 * cur (running, so in no list) is queued at the tail. Someone is ready.
 * ready_pop and then the tail's append in ready_insert do the same, 13
 * cycles a yield slower (bench/avr_bench.py --cycles). */
static OS_HOT sys_tcb *ready_rotate(sys_tcb *cur) {
    sys_tcb *first = os.ready;
    sys_tcb *rest = first->next;
    cur->next = NULL;
    if (rest == NULL) {
        os.ready = cur;
    } else {
        os.ready = rest;
        os.ready_tail->next = cur;
    }
    os.ready_tail = cur;
    os.slice_left = os.slice_ms; /* a fresh turn */
    return first;
}

/* The running thread cur - its guard checked, no work for the system
 * thread, someone ready - goes back to the ready list through the policy
 * and the head runs (cur again if it still comes first): the decision
 * os_decide would take, without its general checks. switch_to is spelled
 * out (no yield request is pending here): calling it, and os_make_ready
 * for round robin, cost 44 more cycles a yield (bench/avr_bench.py). */
static OS_HOT void rotate(sys_tcb *cur) {
    cur->state = SYS_PROCESS_READY;
    sys_tcb *next;
    if (os.policy == &sys_scheduler_round_robin) {
        next = ready_rotate(cur);
    } else {
        os_make_ready(cur);
        os.reconsider = false; /* this rotation is the decision it asks for */
        next = ready_pop();
    }
    next->state = SYS_PROCESS_RUNNING;
    if (next == cur) return;
    count_switch();
    os.current = next;
    port_switch(&cur->ctx, &next->ctx);
}

/* Sys_Yield: a running thread outside any critical section, interrupts
 * masked. The common case - nothing for the system thread to do, someone
 * ready - rotates directly; anything else takes the general decision. */
void os_yield(void) {
    sys_tcb *cur = os.current;
    if (os.ready == NULL || os_system_work_pending() || !os_stack_guard_intact(cur)) {
        os.yield_requested = true;
        os_schedule();
        os.yield_requested = false;
        return;
    }
    rotate(cur);
}

/* May the tick that ends the running thread's slice take the plain way
 * (os_slice_over)? A user thread runs outside any critical section, no
 * interrupt is nested, its guard is intact and the system thread has no
 * work: the general decision would rotate, or renew the slice of a thread
 * nobody waits behind. Reads only. The last two are os_yield's test,
 * written out in each: a helper for both made avr-gcc lay out both chains
 * worse (3 to 14 cycles on the yield and the tick, bench/avr_bench.py
 * --cycles). */
bool os_slice_end_is_plain(void) {
    sys_tcb *cur = os.current;
    return (os.isr_depth | os.lock_depth) == 0 && cur != OS_SYSTEM && !os_system_work_pending() &&
           os_stack_guard_intact(cur);
}

/* The slice ended (counted by the tick) on the plain way: the decision
 * the end of the tick's interrupt would take, without the interrupt's
 * entry, the general tick and the general decision around it. A lone
 * busy thread gets a fresh slice, as must_rotate would give it. */
void os_slice_over(void) {
    os.reconsider = false; /* this decision sees every change */
    if (os.ready == NULL)
        os.slice_left = os.slice_ms;
    else
        rotate(os.current);
}

/* With the tick stopped (tickless idle), the port first credits the time
 * that passed: the interrupt's handler may read it or start a timeout. */
void os_isr_enter(void) {
#if OS_CFG_TICKLESS
    port_tickless_wake();
#endif
    os.isr_depth++;
}

/* The outermost interrupt's end decides at once (no guard check: the tick
 * makes one), if anything the decision reads has changed. */
void os_isr_exit(void) {
    if (--os.isr_depth != 0) return;
    if (!OS_THREADS_RUN || os.current == OS_SYSTEM)
        os_program_preempted();
    else if (os.reconsider)
        os_decide();
}

sys_status Sys_Set_Scheduler(const sys_scheduler *scheduler) {
    if (scheduler == NULL || scheduler->insert == NULL || scheduler->preempts == NULL)
        return SYS_E_INVALID;
    port_irq_state_t s = port_irq_save();
    sys_tcb *list = os.ready;
    os.ready = NULL;
    os.policy = scheduler;
    while (list != NULL) { /* re-queue everyone under the new policy */
        sys_tcb *t = list;
        list = t->next;
        t->next = NULL;
        ready_insert(t);
    }
    os.reconsider = true; /* an interrupt's end decides again */
    os_schedule();
    port_irq_restore(s);
    return SYS_OK;
}

const sys_scheduler *Sys_Get_Scheduler(void) { return os.policy; }

sys_status Sys_Set_TimeSlice(uint16_t ms) {
    if (ms == 0) return SYS_E_INVALID;
    port_irq_state_t s = port_irq_save();
    os.slice_ms = ms;
    if (os.slice_left > ms) os.slice_left = ms;
    port_irq_restore(s);
    return SYS_OK;
}
