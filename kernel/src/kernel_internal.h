/* Kernel-private state and the functions the kernel's modules share. */
#ifndef OPENSWARM_KERNEL_INTERNAL_H
#define OPENSWARM_KERNEL_INTERNAL_H

#include "openswarm/kernel.h"
#include "openswarm/port.h"

/* Small functions on the scheduling and dispatch paths: inlined even where
 * -Os would rather call them, because a call and its register saves cost
 * more cycles than their bodies. */
#if defined(__GNUC__)
#define OS_HOT inline __attribute__((always_inline))
#else
#define OS_HOT inline
#endif

/* Cold code kept out of line even where link-time optimisation would copy
 * it into its callers: code many callers share (a call is smaller), and
 * rare work whose registers a hot caller would otherwise save every time. */
#if defined(__GNUC__)
#define OS_COLD __attribute__((noinline))
#else
#define OS_COLD
#endif

/* State of an unused thread slot (never visible through the API). */
#define OS_SLOT_FREE 0xFFu
#define OS_SYSTEM (&os.threads[0])
/* Event id of a wait that waits for no event (Sys_Sleep). */
#define OS_NO_EVENT ((sys_event_id)0xFF)

/* The stack pool: every stack also gets the port's extra bytes. */
#define OS_STACK_POOL_TOTAL \
    (OS_CFG_STACK_POOL_BYTES + (OS_CFG_MAX_THREADS - 1) * PORT_STACK_EXTRA)
#define OS_STACK_BLOCKS \
    ((OS_STACK_POOL_TOTAL + OS_CFG_STACK_BLOCK_BYTES - 1) / OS_CFG_STACK_BLOCK_BYTES)
#if OS_STACK_BLOCKS > 255
typedef uint16_t os_block_count; /* hosts: large stacks */
#else
typedef uint8_t os_block_count; /* robots: one byte per thread less */
#endif

/* What a blocked thread waits for. It lives on the waiting thread's stack,
 * which stays untouched while the thread is blocked, so a TCB only needs a
 * pointer to it. */
typedef struct os_wait {
    uint8_t *buffer;
    sys_event_condition condition;
    uint32_t deadline; /* when timed: the os.now_ms at which the wait ends */
    sys_event_id event;
    uint8_t capacity;
    uint8_t size;
    sys_status status;
    bool timed;
} os_wait;

struct sys_tcb {
    port_context_t ctx;
    sys_tcb *next;    /* ready list */
    os_wait *wait;    /* set while BLOCKED */
    uint8_t *stack;   /* lowest address: the guard lives here */
    os_block_count stack_blocks;
    uint8_t state;    /* sys_process_state or OS_SLOT_FREE */
    uint8_t priority;
    sys_pid pid;
};

typedef struct os_kernel {
    sys_tcb threads[OS_CFG_MAX_THREADS]; /* [0] is the system thread */
    sys_tcb *current;
    sys_tcb *ready;     /* ordered by the scheduling policy */
    sys_tcb *ready_tail; /* its last thread, while it has one (scheduler.c) */
    sys_tcb *preempted; /* thread to resume once the system thread's work is done */
    const sys_scheduler *policy;
    uint32_t now_ms;
    uint32_t timeout_next; /* the nearest deadline, or a time already past if none (wait.c) */
    uint8_t switches[4]; /* thread-to-thread switches, lowest byte first (scheduler.c) */
    uint16_t slice_ms;
    uint16_t slice_left; /* 0: the running thread's slice is over */
    uint8_t queued_bytes; /* in the event queue's ring */
    uint8_t held_event;   /* id + 1 of the occurrence held in its kept data, 0: none */
    uint8_t handling_event; /* id + 1 of the event whose handlers run, 0: none */
#if OS_CFG_HANDLER_LIMIT_MS
    uint16_t handler_ms; /* ticks the running handler has taken so far */
#endif
    /* How many of the coming ticks need no look at the deadlines, the
     * handler watch or the clock event: the tick counts them down and,
     * if the slice does not end either, does nothing else (system_time.c). */
#if OS_CFG_QUIET_TICK
    uint8_t quiet_ticks;
#endif
    uint8_t event_waiters; /* threads blocked on an event: none means no waiter scan */
    uint8_t lock_depth; /* critical-section nesting of the running thread */
    uint8_t isr_depth;
    bool yield_requested;
    /* Something a decision reads changed since the last one: the ready
     * list, a priority, the policy, the end of a slice, or the system
     * thread's work (an event sent, a thread ended, a stop). The end of an
     * interrupt decides only if so (os_isr_exit): the common tick, in the
     * middle of a slice, then costs no decision. Set by whoever changes
     * these, cleared by the decision that sees them. */
    bool reconsider;
    uint8_t system_work; /* OS_WORK_*: one byte, so a decision reads both at once */
    /* The system thread runs its program (Sys_Run_SystemProgram), not the
     * kernel's work: what is sent meanwhile is dispatched at once. */
    bool program_running;
#if OS_CFG_CLOCK_EVENT
    uint8_t clock_listeners; /* has SYS_EVENT_1MS_TIMER a handler or waiter: OS_CLOCK_* */
#endif
    sys_fault_hook fault_hook;
} os_kernel;

extern os_kernel os;
/* The resource counters (Sys_Get_Stats), apart from os under a name of
 * their own: the simulator reads them from the firmware's RAM by that name
 * (openswarm-sim --counters). */
extern sys_stats os_stats;

/* The system thread's work besides the events (os.system_work). */
#define OS_WORK_REAP 1u /* a thread ended: its slot and stack to free */
#define OS_WORK_STOP 2u /* Sys_Stop_Kernel: the system thread returns */
static OS_HOT bool os_reap_pending(void) { return (os.system_work & OS_WORK_REAP) != 0; }

/* Has the system thread work to do (on every scheduling decision)? */
static OS_HOT bool os_system_work_pending(void) {
    uint8_t work = (uint8_t)(os.queued_bytes | os.held_event);
    work |= os.system_work;
    return work != 0;
}

/* Something the quiet ticks were reckoned from changed (a new deadline,
 * handlers start, the clock event's listeners): the next tick looks. */
#if OS_CFG_QUIET_TICK
static OS_HOT void os_tick_look_again(void) { os.quiet_ticks = 0; }
/* The rest of the tick is out of line, so the quiet tick's interrupt saves
 * no registers for it; without the quiet tick it is inlined (less flash). */
#define OS_TICK_COLD OS_COLD
#else
static OS_HOT void os_tick_look_again(void) {}
#define OS_TICK_COLD
#endif

/* Handlers or waiters of event may have come or gone: if it is the 1 ms
 * clock event, the next tick asks again whether it has any (instead of
 * every millisecond; system_time.c). */
#if OS_CFG_CLOCK_EVENT
#define OS_CLOCK_UNKNOWN 0u /* what a reset leaves: ask at the next tick */
#define OS_CLOCK_UNHEARD 1u
#define OS_CLOCK_HEARD 2u
static OS_HOT void os_listeners_changed(sys_event_id event) {
    if (event != SYS_EVENT_1MS_TIMER) return;
    os.clock_listeners = OS_CLOCK_UNKNOWN;
    os_tick_look_again();
}
#else
static OS_HOT void os_listeners_changed(sys_event_id event) { (void)event; }
#endif

/* process.c */
sys_tcb *os_thread_of(sys_pid pid); /* NULL if pid is not a live thread */
void os_terminate(sys_tcb *t);      /* make t a zombie and detach it from everything */
void os_reap_zombies(void);

/* scheduler.c */
void os_scheduler_reset(void);
void os_make_ready(sys_tcb *t);
void os_ready_remove(sys_tcb *t);
void os_schedule(void);              /* switch if something else should run now */
void os_yield(void);                 /* Sys_Yield's decision */
bool os_slice_end_is_plain(void);    /* the slice's end needs only a rotation or a renewal */
void os_slice_over(void);            /* ... which os_tick_quiet then takes */
/* Switch to whoever should run now; false if the caller goes on (the
 * system thread: nobody else can run). */
bool os_decide(void);

/* stack_pool.c */
/* Give t (a free slot) a stack of at least bytes (plus the port's extra and
 * the guard): its size, or 0 if there is no room. It stays the thread's
 * until the thread's stack pointer is cleared. */
size_t os_stack_alloc(sys_tcb *t, uint16_t bytes);
#if OS_CFG_STACK_CHECK
/* The pattern in the lowest bytes of every thread stack; checked at every
 * scheduling decision a thread makes and at every tick that leads to one
 * (at least once a slice), so overwriting it
 * (an overflow) is caught. Compared as one 32-bit number against a
 * constant: a few cycles on an 8-bit CPU, not a memcmp call. */
#define OS_STACK_GUARD_BYTES 4u
#define OS_STACK_GUARD {0xA5u, 0x5Au, 0xC3u, 0x3Cu}
/* What free stack bytes hold (stack_pool.c); openswarm-sim knows it too
 * (sim/src/board/thread_stacks.c). */
#define OS_STACK_PAINT 0xE7u
void os_stack_pool_reset(void); /* every stack free: painted */
void os_stack_free(sys_tcb *t); /* t's stack painted, then t's no more */
static OS_HOT bool os_stack_guard_intact(const sys_tcb *t) {
    static const uint8_t guard[OS_STACK_GUARD_BYTES] = OS_STACK_GUARD;
    const uint8_t *g = t->stack;
    if (g == NULL) return true;
    uint32_t have = g[0] | (uint32_t)g[1] << 8 | (uint32_t)g[2] << 16 | (uint32_t)g[3] << 24;
    return have == (guard[0] | (uint32_t)guard[1] << 8 | (uint32_t)guard[2] << 16 | (uint32_t)guard[3] << 24);
}

void os_stack_overflowed(sys_tcb *t); /* its guard is broken: stop it */
/* The check a thread's own decisions and the tick make (not inside a
 * critical section); the guard is compared here, inline, so an intact one
 * costs no call. */
static OS_HOT void os_check_stack(sys_tcb *t) {
    if (os.lock_depth == 0 && !os_stack_guard_intact(t)) os_stack_overflowed(t);
}
#else
/* No guard (OS_CFG_STACK_CHECK 0): every stack passes. */
#define OS_STACK_GUARD_BYTES 0u
static OS_HOT bool os_stack_guard_intact(const sys_tcb *t) {
    (void)t;
    return true;
}
static OS_HOT void os_check_stack(sys_tcb *t) { (void)t; }
static inline void os_stack_pool_reset(void) {}
static inline void os_stack_free(sys_tcb *t) { t->stack = NULL; }
#endif

/* event_table.c */
/* One slot per event id: the event's data block and what it keeps. Two
 * sizes no occurrence can have (capacities stop at SYS_EVENT_DATA_MAX) mark
 * a slot's state, so a slot is 4 bytes on an 8-bit CPU. The queue reads and
 * fills slots directly: a call per occurrence costs tens of cycles. */
#define OS_EVENT_UNREGISTERED 0xFFu /* the event is not registered */
#define OS_EVENT_NOTHING_KEPT 0xFEu /* registered, no occurrence kept (yet, or cleared) */
typedef struct os_event_slot {
    uint8_t *data; /* capacity bytes; NULL when the capacity is 0 */
    uint8_t capacity;
    uint8_t size; /* bytes kept, or OS_EVENT_UNREGISTERED / OS_EVENT_NOTHING_KEPT */
} os_event_slot;
extern os_event_slot os_events[OS_CFG_MAX_EVENTS];

void os_event_table_reset(void);
bool os_event_registered(sys_event_id event);
#if OS_CFG_CLOCK_EVENT
bool os_event_has_listeners(sys_event_id event);
#endif
void os_subscriptions_remove_thread(sys_pid pid);
void os_run_handlers(const sys_event_data *data);

/* event_queue.c */
void os_event_queue_reset(void); /* after os is cleared */
/* Queue an occurrence of event (< OS_CFG_MAX_EVENTS, interrupts masked):
 * SYS_OK, or why not; a full queue is counted. */
sys_status os_event_post(sys_event_id event, const void *data, uint8_t size);
static OS_HOT bool os_event_queue_empty(void) { return (os.queued_bytes | os.held_event) == 0; }
/* Is the event's occurrence held in its kept data, not yet dispatched? */
static OS_HOT bool os_event_queue_holds(sys_event_id event) { return os.held_event == (uint8_t)(event + 1u); }
/* The event was unregistered: an occurrence held for it goes (counted). */
void os_event_queue_forget(sys_event_id event);
/* Pop one occurrence into the event's kept data and describe it in *out;
 * false if it had to be discarded (event unregistered meanwhile). */
bool os_event_queue_pop(sys_event_data *out);

/* event_dispatch.c */
void os_dispatch_all(void);
void os_dispatch_on_system_stack(void);

/* wait.c */
void os_wake_waiters(const sys_event_data *data);
void os_wait_abandon(sys_tcb *t); /* t stops waiting: woken or killed */
void os_wake_all_waiting_for(sys_event_id event, sys_status status);
/* From a tick that looks, once os.now_ms has advanced: the waits whose
 * deadline came end, and the quiet ticks are those before the nearest
 * deadline left, as far as a byte counts. */
void os_check_timeouts(void);

/* system_time.c: the system thread has nothing to run; it sleeps until
 * an interrupt (with OS_CFG_TICKLESS, with the tick stopped until the next
 * deadline if nothing needs it sooner). Interrupts masked. */
void os_idle(void);
void os_idle_at_most(uint32_t max_ms); /* and wakes after max_ms at the latest */

/* system_program.c: an event was sent or an interrupt ends while the system
 * thread may be running its program: the handlers run now, on its stack.
 * Interrupts masked. */
void os_program_preempted(void);

/* fault.c */
void os_fault(sys_fault fault, sys_pid pid);
void os_stats_reset(void);
/* counter++ (interrupts masked): out of line, as a call is a third of the
 * code of a 16-bit increment on an 8-bit CPU. */
OS_COLD void os_count(uint16_t *counter);

/* hal.c */
void os_hal_reset(void);

#endif
