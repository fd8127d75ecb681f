/* The 1 ms tick: system time, time slices, timeouts, and the clock event. */
#include "kernel_internal.h"

void os_tick(void) {
    os.now_ms++;
    if (os.current != OS_SYSTEM || os.preempted != NULL) {
        if (os.slice_left != 0 && --os.slice_left == 0) os.slice_expired = true;
    }
    os_check_stack(os.current);
    os_check_timeouts();
    if (!os.clock_listeners_known) {
        os.clock_has_listeners =
            os_event_registered(SYS_EVENT_1MS_TIMER) && os_event_has_listeners(SYS_EVENT_1MS_TIMER);
        os.clock_listeners_known = true;
    }
    if (os.clock_has_listeners) {
        uint32_t now = os.now_ms;
        os_event_post(SYS_EVENT_1MS_TIMER, &now, (uint8_t)sizeof now);
    }
}

uint32_t Sys_Get_SystemTime(void) {
    port_irq_state_t s = port_irq_save(); /* 32 bits are not atomic on 8-bit CPUs */
    uint32_t now = os.now_ms;
    port_irq_restore(s);
    return now;
}
