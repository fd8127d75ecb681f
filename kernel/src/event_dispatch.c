/* Sending events and dispatching them, one occurrence at a time, in the
 * system thread: first the waiting threads it satisfies are made ready,
 * then the subscribed handlers run to completion. */
#include "kernel_internal.h"

sys_status Sys_Send_Event(sys_event_id event, const void *data, uint8_t size) {
    if (event >= OS_CFG_MAX_EVENTS || (data == NULL && size != 0)) return SYS_E_INVALID;
    port_irq_state_t s = port_irq_save();
    sys_status st = os_event_post(event, data, size);
    if (st == SYS_OK && os.isr_depth == 0) os_schedule(); /* a thread's: handlers now; an ISR's: at its exit */
    port_irq_restore(s);
    return st;
}

sys_status Sys_Send_IntEvent(sys_event_id event, int16_t value) {
    return Sys_Send_Event(event, &value, (uint8_t)sizeof value);
}

/* The occurrence being dispatched. Only the system thread dispatches and
 * a handler's sends are queued, never dispatched inside it, so one static
 * copy serves (no stack frame on the way to the first handler). */
static sys_event_data occurrence;

/* As the system thread, interrupts masked: until the queue is empty, or a
 * handler has ended a thread. Reaping comes first, so what a later handler
 * starts can have the ended thread's slot and stack. (When called on behalf
 * of a thread, the rest is dispatched by the system thread before that
 * thread runs on.) */
void os_dispatch_all(void) {
    while (!os_event_queue_empty() && !os_reap_pending()) {
        if (!os_event_queue_pop(&occurrence)) continue;
        os_wake_waiters(&occurrence);
        os_run_handlers(&occurrence);
    }
}

/* From a running thread, or an interrupt that ends: the handlers run at
 * once, as the system thread and on its stack, and the thread goes on. */
void os_dispatch_on_system_stack(void) {
    sys_tcb *interrupted = os.current;
    os.current = OS_SYSTEM;
    port_call_on_system_stack(&OS_SYSTEM->ctx, os_dispatch_all);
    os.current = interrupted;
}
