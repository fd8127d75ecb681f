/* Blocking: waiting for an event (optionally with a condition on its data
 * and a timeout) and sleeping. Every blocked thread describes its wait in
 * an os_wait on its own stack, so any number of threads can wait for the
 * same event and each is woken with its own copy of the data. */
#include "kernel_internal.h"

static void settle_timeouts(void);

/* The running thread's timed wait w starts: it ends timeout_ms from now.
 * Out of line, so an untimed wait saves no registers for its 32-bit
 * arithmetic. */
static OS_COLD void start_timeout(os_wait *w, uint32_t timeout_ms) {
    w->deadline = os.now_ms + timeout_ms;
    settle_timeouts(); /* w's may be the nearest deadline now (none is due) */
    os_tick_look_again(); /* and nearer than the quiet ticks reach */
}

/* The running thread blocks on w until woken: the status it is woken with
 * (every waker sets one). */
static sys_status block_current(os_wait *w, sys_event_id event, bool timed, uint32_t timeout_ms) {
    if (event != OS_NO_EVENT) { /* a sleep listens to nothing */
        os.event_waiters++;
        os_listeners_changed(event);
    }
    w->event = event;
    w->timed = timed;
    sys_tcb *cur = os.current;
    cur->wait = w;
    cur->state = SYS_PROCESS_BLOCKED;
    if (timed) start_timeout(w, timeout_ms); /* w is not due: timeout_ms > 0 */
    os_schedule(); /* returns once woken */
    return w->status;
}

/* Only a thread of the app's may wait: not the system thread (handlers),
 * an interrupt or a critical section. */
static inline bool may_block(void) {
    return OS_CFG_MAX_THREADS > 1 && (os.isr_depth | os.lock_depth) == 0 && os.current != OS_SYSTEM;
}

/* The running thread waits as w says (the caller sets what an event's
 * waker reads: buffer, condition, capacity, size): the status it is woken
 * with, or why it cannot wait. The event and the kind of wait come as
 * arguments, not through w, so a caller's constants fold: a sleep's tests
 * vanish and it sets only what the tick and the wakers read. */
static sys_status block(os_wait *w, sys_event_id event, bool timed, uint32_t timeout_ms) {
    if (!may_block()) return SYS_E_CONTEXT;
    port_irq_state_t s = port_irq_save();
    sys_status st;
    if (event != OS_NO_EVENT && !os_event_registered(event))
        st = SYS_E_NOT_REGISTERED;
    else if (timed && timeout_ms == 0)
        st = SYS_E_TIMEOUT;
    else
        st = block_current(w, event, timed, timeout_ms);
    port_irq_restore(s);
    return st;
}

static sys_status wait_for(sys_event_id event, sys_event_condition condition, bool timed,
                           uint32_t timeout_ms, void *buffer, uint8_t capacity, uint8_t *size) {
    if (buffer == NULL && capacity != 0) return SYS_E_INVALID;
    os_wait w;
    w.buffer = (uint8_t *)buffer;
    w.condition = condition;
    w.capacity = capacity;
    w.size = 0;
    sys_status st = block(&w, event, timed, timeout_ms);
    if (size != NULL) *size = w.size;
    return st;
}

sys_status Sys_Wait_for_Event(sys_event_id event, void *buffer, uint8_t capacity, uint8_t *size) {
    if (event >= OS_CFG_MAX_EVENTS) return SYS_E_INVALID;
    return wait_for(event, NULL, false, 0, buffer, capacity, size);
}

sys_status Sys_Wait_for_Condition(sys_event_id event, sys_event_condition condition, void *buffer,
                                  uint8_t capacity, uint8_t *size) {
    if (event >= OS_CFG_MAX_EVENTS || condition == NULL) return SYS_E_INVALID;
    return wait_for(event, condition, false, 0, buffer, capacity, size);
}

sys_status Sys_Wait_for_Event_Timeout(sys_event_id event, uint32_t timeout_ms, void *buffer,
                                      uint8_t capacity, uint8_t *size) {
    if (event >= OS_CFG_MAX_EVENTS) return SYS_E_INVALID;
    return wait_for(event, NULL, true, timeout_ms, buffer, capacity, size);
}

sys_status Sys_Wait_for_Condition_Timeout(sys_event_id event, sys_event_condition condition,
                                          uint32_t timeout_ms, void *buffer, uint8_t capacity,
                                          uint8_t *size) {
    if (event >= OS_CFG_MAX_EVENTS || condition == NULL) return SYS_E_INVALID;
    return wait_for(event, condition, true, timeout_ms, buffer, capacity, size);
}

sys_status Sys_Sleep(uint32_t ms) {
    os_wait w; /* only woken by its timeout: no buffer, condition or size */
    sys_status st = block(&w, OS_NO_EVENT, true, ms);
    return st == SYS_E_TIMEOUT ? SYS_OK : st;
}

sys_status Sys_Sleep_Until(uint32_t *wake_ms, uint32_t period_ms) {
    if (wake_ms == NULL) return SYS_E_INVALID;
    if (!may_block()) return SYS_E_CONTEXT;
    /* The time left is taken with interrupts masked, through to blocking:
     * a tick in between would make the wake-up a millisecond late. */
    port_irq_state_t s = port_irq_save();
    uint32_t target = *wake_ms + period_ms;
    int32_t left = (int32_t)(target - os.now_ms);
    *wake_ms = target;
    sys_status st = left <= 0 ? SYS_OK : Sys_Sleep((uint32_t)left);
    port_irq_restore(s);
    return st;
}

/* The thread stops waiting (woken, or killed): it no longer counts. */
static OS_HOT void leave_wait(sys_tcb *t, const os_wait *w) {
    sys_event_id event = w->event; /* read once: the byte stores below may alias it */
    if (event != OS_NO_EVENT) {
        os.event_waiters--;
        os_listeners_changed(event);
    }
    t->wait = NULL;
}

void os_wait_abandon(sys_tcb *t) {
    if (t->wait != NULL) leave_wait(t, t->wait);
}

/* Out of line: the dispatch and the timeouts share it. The status is
 * stored last: a byte store may alias t->wait, which would then be read
 * again. */
static OS_COLD void wake(sys_tcb *t, sys_status status) {
    os_wait *w = t->wait;
    leave_wait(t, w);
    w->status = status;
    os_make_ready(t);
}

/* The occurrence satisfies t's wait w: its data into the wait's buffer
 * (as much as fits), and t woken. */
static OS_HOT void take(sys_tcb *t, os_wait *w, const sys_event_data *data) {
    const uint8_t *src = (const uint8_t *)data->value;
    uint8_t *dst = w->buffer;
    for (uint8_t n = data->size < w->capacity ? data->size : w->capacity; n != 0; n--)
        *dst++ = *src++; /* a few bytes: no memcpy call */
    w->size = data->size;
    wake(t, data->size > w->capacity ? SYS_E_TRUNCATED : SYS_OK);
}

/* Dispatch of one occurrence: wake every thread whose wait it satisfies.
 * A thread's wait is set exactly while it is blocked. The scan ends at the
 * last thread that waits for an event (os.event_waiters counts them), not
 * at the last slot: none at all, the common case, costs one test. */
void os_wake_waiters(const sys_event_data *data) {
    uint8_t left = os.event_waiters;
    if (left == 0) return;
    for (sys_tcb *t = &os.threads[1]; t != &os.threads[OS_CFG_MAX_THREADS]; t++) {
        os_wait *w = t->wait;
        if (w == NULL || w->event == OS_NO_EVENT) continue; /* running, or asleep */
        bool last = --left == 0;
        if (w->event == data->event && (w->condition == NULL || w->condition(data))) take(t, w, data);
        if (last) return;
    }
}

void os_wake_all_waiting_for(sys_event_id event, sys_status status) {
    for (sys_tcb *t = &os.threads[1]; t != &os.threads[OS_CFG_MAX_THREADS]; t++)
        if (t->wait != NULL && t->wait->event == event) wake(t, status); /* wait: set while blocked */
}

/* Timeouts. Each timed wait keeps its deadline and os.timeout_next the
 * nearest one, so the tick compares one number and visits the waits only
 * when that deadline comes, or when a new timed wait may come sooner.
 * Distances to deadlines are taken modulo 2^32 from now, so any 32-bit
 * timeout works; os.timeout_next == now_ms means none is pending (the tick
 * meets that value again only after 2^32 ms, and then finds nothing due). */
static OS_COLD void settle_timeouts(void) {
    uint32_t nearest = 0; /* ms from now; 0: none */
    for (sys_tcb *t = &os.threads[1]; t != &os.threads[OS_CFG_MAX_THREADS]; t++) {
        os_wait *w = t->wait; /* set exactly while t is blocked */
        if (w == NULL || !w->timed) continue;
        uint32_t left = w->deadline - os.now_ms;
        if (left == 0)
            wake(t, SYS_E_TIMEOUT);
        else if (left - 1u < nearest - 1u) /* sooner: none (0) wraps to the farthest */
            nearest = left;
    }
    os.timeout_next = os.now_ms + nearest;
}

OS_TICK_COLD void os_check_timeouts(void) {
    if (os.now_ms == os.timeout_next) settle_timeouts();
#if OS_CFG_QUIET_TICK
    uint32_t left = os.timeout_next - os.now_ms; /* to the nearest deadline; 0: none (wraps to 255) */
    os.quiet_ticks = left > UINT8_MAX ? UINT8_MAX : (uint8_t)((uint8_t)left - 1u);
#endif
}
