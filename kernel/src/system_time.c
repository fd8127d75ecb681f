/* The 1 ms tick: system time, time slices, timeouts, the handler watch and
 * the clock event; and the idle system thread's sleep, which with
 * OS_CFG_TICKLESS lets the port stop the tick until the next deadline.
 *
 * Most ticks are quiet: they count the time and the slice and nothing
 * else. os.quiet_ticks says how many of the coming ticks need no look at
 * the deadlines, the handler watch or the clock event; a tick that looks
 * reckons it again from the nearest deadline (none while handlers run or
 * the clock event has a listener: every tick looks then), and whatever
 * brings a need nearer (a new deadline, handlers starting, the clock
 * event's listeners) makes the next tick look. */
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

/* The time's lowest byte. (A compiler that does not say its byte order is
 * taken to be little-endian, as every robot's CPU is.) */
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
#define NOW_LOW_BYTE (sizeof os.now_ms - 1u)
#else
#define NOW_LOW_BYTE 0u
#endif

/* The lowest byte wrapped: the others take the carry. */
static OS_TICK_COLD void carry_time(void) { os.now_ms += 0x100u; }

/* now_ms++ adds to the lowest byte alone but once in 256 ticks, as the
 * switch count does: on an 8-bit CPU 7 cycles a tick instead of 20. */
static OS_HOT void advance_time(void) {
    uint8_t *low = (uint8_t *)&os.now_ms + NOW_LOW_BYTE;
    if (++*low == 0) carry_time();
}

/* The running thread's slice runs out: the end of the tick decides. It is
 * counted whoever runs: a slice nobody holds (the system thread's own
 * turn, no thread parked in os.preempted) is never read again, as the
 * next thread to run gets a fresh one. */
static OS_HOT void count_slice(void) {
    if (os.slice_left != 0 && --os.slice_left == 0) os.reconsider = true;
}

/* The handler watch and the clock event, at a tick that looks: while
 * handlers run, or while the clock event has a listener, every tick looks. */
static void look_at_handlers_and_clock(void) {
#if OS_CFG_HANDLER_LIMIT_MS
    if (os.handling_event != 0) {
        os_tick_look_again(); /* the watch counts every tick */
        /* A handler that never returns holds up everything the system
         * thread does: said once, when it reaches the limit. */
        if (++os.handler_ms == OS_CFG_HANDLER_LIMIT_MS) {
            os_count(&os_stats.handler_overruns);
            os_fault(SYS_FAULT_HANDLER_OVERRUN, SYS_PID_SYSTEM);
        }
    }
#endif
#if OS_CFG_CLOCK_EVENT
    if (clock_heard()) {
        os_tick_look_again(); /* every tick is an occurrence */
        /* The tick runs with interrupts masked: now_ms cannot change while
         * it is copied, so it needs no copy on the interrupt's stack. */
        os_event_post(SYS_EVENT_1MS_TIMER, &os.now_ms, (uint8_t)sizeof os.now_ms);
    }
#endif
}

/* The slice's count and the stack guard, at every tick that is not quiet.
 * The guard is checked by the ticks that lead to a decision - at least
 * the last of every slice - not by every tick: 25 cycles off the common
 * tick, and a thread that overflows while it spins is still stopped within
 * a slice (and at its own next decision). */
static OS_TICK_COLD void count_slice_and_check_guard(void) {
    count_slice();
    if (os.reconsider) os_check_stack(os.current);
}

/* Any tick (a port may take every tick this way), and the one
 * os_tick_quiet refuses: the slice ends, or the quiet ticks are over and
 * this tick looks at the deadlines, the handler watch and the clock event
 * (in the order every tick once took them) and reckons the quiet ticks
 * again. Out of line: an interrupt's quiet tick then saves no registers
 * for it. */
OS_TICK_COLD void os_tick(void) {
    advance_time();
#if OS_CFG_QUIET_TICK
    if (os.quiet_ticks != 0) {
        os.quiet_ticks--;
        count_slice_and_check_guard();
        return;
    }
#endif
    os_check_timeouts();
    count_slice_and_check_guard();
    look_at_handlers_and_clock();
}

#if OS_CFG_QUIET_TICK
/* A quiet tick that ends the slice, when the decision it leads to is a
 * plain rotation (or a lone thread's fresh slice): counted, then taken.
 * Out of line: the common quiet tick's interrupt then saves no more
 * registers. */
static OS_COLD bool tick_ending_slice(void) {
    if (!os_slice_end_is_plain()) return false;
    os.quiet_ticks--;
    advance_time();
    os_slice_over(); /* the slice's count: a fresh one, whoever runs on */
    return true;
}
#endif

/* Most ticks need nothing but the time and the slice's count: no deadline
 * comes, no handler runs, the clock event has no listener and the slice
 * does not end. The end of such a tick's interrupt has no decision to
 * take either (a thread outside a critical section has none pending;
 * inside one, or on the system thread, the end of an interrupt takes
 * none), so it needs no os_isr_enter/os_isr_exit. The tick that ends a
 * slice takes this way too when the decision is a plain rotation, or a
 * fresh slice for a thread nobody waits behind
 * (tick_ending_slice). */
bool os_tick_quiet(void) {
#if OS_CFG_QUIET_TICK
    uint16_t slice = os.slice_left;
    if (os.quiet_ticks == 0) return false;
    if (slice == 1) return tick_ending_slice();
    os.quiet_ticks--;
    if (slice != 0) os.slice_left = slice - 1u; /* 0: over, or nobody's */
    advance_time();
    return true;
#else
    return false; /* every tick takes os_tick */
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
 * recomputed from there, and the quiet ticks with it (no handler runs and
 * the clock event has no listener while the tick is stopped). */
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
