/* The 1 ms tick: system time, time slices, timeouts, and the clock event;
 * and the idle system thread's sleep, which with OS_CFG_TICKLESS lets the
 * port stop the tick until the next deadline. */
#include "kernel_internal.h"

#if OS_CFG_TICKLESS && !defined(PORT_TICKLESS_IDLE)
#error "OS_CFG_TICKLESS 1 needs a port with tickless idle (the Kilobot's): set OS_CFG_TICKLESS to 0 in the app's config (openswarm.json: \"kernel\": {\"tickless\": false})"
#endif

#if OS_CFG_CLOCK_EVENT
/* Has the clock event a handler or waiter? An unregistered event has none:
 * unregistering ends its subscriptions and wakes its waiters. Asked again
 * only after they changed. */
static OS_HOT bool clock_heard(void) {
    if (os.clock_listeners == OS_CLOCK_UNKNOWN)
        os.clock_listeners =
            os_event_has_listeners(SYS_EVENT_1MS_TIMER) ? OS_CLOCK_HEARD : OS_CLOCK_UNHEARD;
    return os.clock_listeners == OS_CLOCK_HEARD;
}
#endif

void os_tick(void) {
    os.now_ms++;
    os_check_timeouts();
    if (os.current != OS_SYSTEM || os.preempted != NULL) {
        if (os.slice_left != 0 && --os.slice_left == 0) os.reconsider = true; /* the slice is over */
    }
    /* The guard is checked by the ticks that lead to a decision - at least
     * the last of every slice - not by every tick: 25 cycles off the common
     * tick, and a thread that overflows while it spins is still stopped
     * within a slice (and at its own next decision). */
    if (os.reconsider) os_check_stack(os.current);
#if OS_CFG_HANDLER_LIMIT_MS
    /* A handler that never returns holds up everything the system thread
     * does: said once, when it reaches the limit. */
    if (os.handling_event != 0 && ++os.handler_ms == OS_CFG_HANDLER_LIMIT_MS) {
        os_count(&os_stats.handler_overruns);
        os_fault(SYS_FAULT_HANDLER_OVERRUN, SYS_PID_SYSTEM);
    }
#endif
#if OS_CFG_CLOCK_EVENT
    /* The tick runs with interrupts masked: now_ms cannot change while it
     * is copied, so it needs no copy on the interrupt's stack. */
    if (clock_heard()) os_event_post(SYS_EVENT_1MS_TIMER, &os.now_ms, (uint8_t)sizeof os.now_ms);
#endif
}

uint32_t Sys_Get_SystemTime(void) {
    port_irq_state_t s = port_irq_save(); /* 32 bits are not atomic on 8-bit CPUs */
    uint32_t now = os.now_ms;
    port_irq_restore(s);
    return now;
}

#if OS_CFG_TICKLESS
/* Ticks from now until the first one the kernel needs. Only the timeouts
 * and the clock event need ticks while the system thread idles: no thread
 * runs (no slice to count), no handler runs (none to time), no thread's
 * stack is in use. */
static uint32_t ticks_until_needed(void) {
#if OS_CFG_CLOCK_EVENT
    if (clock_heard()) return 1; /* every tick is an occurrence */
#endif
    uint32_t left = os.timeout_next - os.now_ms; /* 0: no timeout pending */
    return left != 0 ? left : UINT32_MAX;
}

/* The time stops at each deadline on the way, as ticks one by one would:
 * every wait ends at its own time, and the nearest deadline is then
 * recomputed from there. */
void os_ticks_slept(uint16_t ticks) {
    while (ticks != 0) {
        uint32_t due = os.timeout_next - os.now_ms; /* 0, or a time past: none pending */
        uint16_t step = due != 0 && due < ticks ? (uint16_t)due : ticks;
        os.now_ms += step;
        ticks -= step;
        os_check_timeouts();
    }
}
#endif

void os_idle(void) { os_idle_at_most(UINT32_MAX); }

/* A program on the system thread waits for a time of its own (kilolib's
 * delay()), which the kernel's deadlines do not know. */
void os_idle_at_most(uint32_t max_ms) {
#if OS_CFG_TICKLESS
    uint32_t ticks = ticks_until_needed();
    port_idle_for(ticks < max_ms ? ticks : max_ms);
#else
    (void)max_ms; /* the tick wakes it every millisecond */
    port_idle();
#endif
}
