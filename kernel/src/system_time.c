/* The 1 ms tick: system time, time slices, timeouts, and the clock event. */
#include "kernel_internal.h"

void os_tick(void) {
    os.now_ms++;
    os_check_timeouts();
    if (os.current != OS_SYSTEM || os.preempted != NULL) {
        if (os.slice_left != 0) os.slice_left--; /* 0: the slice is over */
    }
    os_check_stack(os.current);
#if OS_CFG_HANDLER_LIMIT_MS
    /* A handler that never returns holds up everything the system thread
     * does: said once, when it reaches the limit. */
    if (os.handling_event != 0 && ++os.handler_ms == OS_CFG_HANDLER_LIMIT_MS) {
        os_count(&os_stats.handler_overruns);
        os_fault(SYS_FAULT_HANDLER_OVERRUN, SYS_PID_SYSTEM);
    }
#endif
#if OS_CFG_CLOCK_EVENT
    /* An unregistered event has none: unregistering ends its subscriptions
     * and wakes its waiters. */
    if (os.clock_listeners == OS_CLOCK_UNKNOWN)
        os.clock_listeners =
            os_event_has_listeners(SYS_EVENT_1MS_TIMER) ? OS_CLOCK_HEARD : OS_CLOCK_UNHEARD;
    /* The tick runs with interrupts masked: now_ms cannot change while it
     * is copied, so it needs no copy on the interrupt's stack. */
    if (os.clock_listeners == OS_CLOCK_HEARD)
        os_event_post(SYS_EVENT_1MS_TIMER, &os.now_ms, (uint8_t)sizeof os.now_ms);
#endif
}

uint32_t Sys_Get_SystemTime(void) {
    port_irq_state_t s = port_irq_save(); /* 32 bits are not atomic on 8-bit CPUs */
    uint32_t now = os.now_ms;
    port_irq_restore(s);
    return now;
}
