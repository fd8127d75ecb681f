/* Registered events, the data each one keeps, and handler subscriptions.
 *
 * Event data lives in one static arena. A block stays with its event slot
 * when the event is unregistered, and a later registration of any event
 * reuses the first such block that is large enough, so registering and
 * unregistering in a loop never exhausts the arena.
 *
 * Subscriptions fill the front of one array, in subscription order: a new
 * one goes at the end. An unsubscription only marks its entry, which every
 * walk skips; the array is packed when a new subscription needs the room,
 * and never while handlers run, so a handler that unsubscribes itself or
 * another never makes the dispatch skip a later handler. */
#include "kernel_internal.h"

#include <string.h>

#define UNREGISTERED OS_EVENT_UNREGISTERED
#define NOTHING_KEPT OS_EVENT_NOTHING_KEPT

/* A subscription with a context keeps its binding where the others keep
 * their condition, and a handler no one calls as its mark: no byte more. */
typedef union condition_or_binding {
    sys_event_condition condition;
    const sys_event_binding *binding;
} condition_or_binding;

typedef struct subscription {
    sys_event_handler handler; /* NULL: unsubscribed (until the array is packed) */
    condition_or_binding with;
    sys_event_id event;
    sys_pid pid;
} subscription;

os_event_slot os_events[OS_CFG_MAX_EVENTS];
static uint8_t arena[OS_CFG_EVENT_DATA_BYTES];
#if OS_CFG_EVENT_DATA_BYTES > 255
typedef uint16_t arena_index; /* hosts: a large arena */
#else
typedef uint8_t arena_index; /* robots: 8-bit arithmetic */
#endif
static arena_index arena_used;

static subscription subs[OS_CFG_MAX_SUBSCRIPTIONS];
static subscription *subs_end; /* past the last subscription: the rest is free */

void os_event_table_reset(void) {
    for (os_event_slot *slot = os_events; slot != &os_events[OS_CFG_MAX_EVENTS]; slot++) {
        slot->data = NULL; /* no block yet: the arena starts empty */
        slot->capacity = 0;
        slot->size = UNREGISTERED;
    }
    arena_used = 0;
    subs_end = subs;
}

bool os_event_registered(sys_event_id event) {
    return event < OS_CFG_MAX_EVENTS && os_events[event].size != UNREGISTERED;
}

/* Find capacity bytes for slot (unregistered): the first block of an
 * unregistered event (its own or another's) that is large enough, or new
 * arena. A block of non-zero capacity always has its data, and none is
 * needed for capacity 0. */
static bool take_data_block(os_event_slot *slot, uint8_t capacity) {
    for (os_event_slot *other = os_events; other != &os_events[OS_CFG_MAX_EVENTS]; other++) {
        if (other->size == UNREGISTERED && other->capacity >= capacity) {
            uint8_t *data = slot->data; /* swap: no block is lost */
            uint8_t cap = slot->capacity;
            slot->data = other->data;
            slot->capacity = other->capacity;
            other->data = data;
            other->capacity = cap;
            return true;
        }
    }
    if (capacity > (arena_index)(sizeof arena - arena_used)) return false;
    slot->data = &arena[arena_used];
    slot->capacity = capacity;
    arena_used = (arena_index)(arena_used + capacity);
    return true;
}

/* The registration proper, interrupts masked. Out of line, so the slot is
 * one pointer throughout rather than recomputed from its index. */
static OS_COLD sys_status register_slot(os_event_slot *slot, uint8_t capacity) {
    if (slot->size != UNREGISTERED) return SYS_E_EXISTS;
    if (!take_data_block(slot, capacity)) {
        os_count(&os_stats.event_data_full);
        return SYS_E_POOL_FULL;
    }
    slot->size = NOTHING_KEPT; /* no listener yet: the clock event's state stays */
    return SYS_OK;
}

sys_status Sys_Register_Event_Sized(sys_event_id event, uint8_t capacity) {
    if (event >= OS_CFG_MAX_EVENTS || capacity > SYS_EVENT_DATA_MAX) return SYS_E_INVALID;
#if !OS_CFG_CLOCK_EVENT
    if (event == SYS_EVENT_1MS_TIMER) return SYS_E_INVALID; /* compiled out (config.h) */
#endif
    if (os.isr_depth != 0) return SYS_E_CONTEXT;
    port_irq_state_t s = port_irq_save();
    sys_status st = register_slot(&os_events[event], capacity);
    port_irq_restore(s);
    return st;
}

sys_status Sys_Register_Event(sys_event_id event) {
    return Sys_Register_Event_Sized(event, OS_CFG_DEFAULT_EVENT_DATA);
}

/* The marked entries go; the others move up, in their order. */
static void pack_subscriptions(void) {
    subscription *kept = subs;
    for (const subscription *sub = subs; sub != subs_end; sub++)
        if (sub->handler != NULL) *kept++ = *sub;
    subs_end = kept;
}

/* A subscription ends: its entry is marked. */
static OS_HOT void unsubscribe(subscription *sub) {
    sub->handler = NULL;
    os_listeners_changed(sub->event);
}

/* Remove the subscriptions matching (event or any, pid or any). */
static void remove_subscriptions(sys_event_id event, bool any_event, sys_pid pid, bool any_pid) {
    for (subscription *sub = subs; sub != subs_end; sub++) {
        if ((any_event || sub->event == event) && (any_pid || sub->pid == pid)) sub->handler = NULL;
    }
    os_listeners_changed(any_event ? SYS_EVENT_1MS_TIMER : event); /* any: the clock's too */
}

sys_status Sys_Unregister_Event(sys_event_id event) {
    if (event >= OS_CFG_MAX_EVENTS) return SYS_E_INVALID;
    if (os.isr_depth != 0) return SYS_E_CONTEXT;
    port_irq_state_t s = port_irq_save();
    if (os_events[event].size == UNREGISTERED) {
        port_irq_restore(s);
        return SYS_E_NOT_REGISTERED;
    }
    os_events[event].size = UNREGISTERED; /* the data block stays for reuse */
    os_event_queue_forget(event);
    remove_subscriptions(event, false, 0, true);
    os_wake_all_waiting_for(event, SYS_E_NOT_REGISTERED);
    os_schedule();
    port_irq_restore(s);
    return SYS_OK;
}

bool Sys_IsEventRegistered(sys_event_id event) {
    port_irq_state_t s = port_irq_save();
    bool registered = os_event_registered(event);
    port_irq_restore(s);
    return registered;
}

#if OS_CFG_HANDLER_CONTEXT
/* The mark of a subscription with a context: the dispatch calls its
 * binding's handler instead, never this. */
static bool bound(sys_pid pid, sys_event_id event, const sys_event_data *data) {
    (void)pid;
    (void)event;
    (void)data;
    return true;
}
#endif

/* A subscription of h (with binding b, for a bound one) to event by pid. */
static subscription *find_subscription(sys_event_id event, sys_pid pid, sys_event_handler h,
                                       const sys_event_binding *b) {
    for (subscription *sub = subs; sub != subs_end; sub++) {
        if (sub->handler == h && sub->event == event && sub->pid == pid &&
            (b == NULL || sub->with.binding == b))
            return sub;
    }
    return NULL;
}

/* Is there room for one more subscription? Marked entries make room,
 * except while handlers run (they walk the array). */
static bool subscription_room(void) {
    if (subs_end == &subs[OS_CFG_MAX_SUBSCRIPTIONS] && os.handling_event == 0) pack_subscriptions();
    return subs_end != &subs[OS_CFG_MAX_SUBSCRIPTIONS];
}

static sys_status subscribe(sys_event_id event, sys_pid pid, sys_event_handler handler,
                            condition_or_binding with, const sys_event_binding *binding) {
    port_irq_state_t s = port_irq_save();
    sys_status st = SYS_OK;
    if (!os_event_registered(event)) {
        /* counted: the handler would never run, and the caller rarely checks */
        os_count(&os_stats.subscriptions_refused);
        st = SYS_E_NOT_REGISTERED;
    } else if (pid != SYS_PID_SYSTEM &&
               (os_thread_of(pid) == NULL || os_thread_of(pid)->state == SYS_PROCESS_ZOMBIE)) {
        st = SYS_E_INVALID;
    } else if (find_subscription(event, pid, handler, binding) != NULL) {
        st = SYS_E_EXISTS;
    } else if (!subscription_room()) {
        os_count(&os_stats.subscription_pool_full);
        st = SYS_E_POOL_FULL;
    } else {
        subscription *sub = subs_end++;
        sub->handler = handler;
        sub->with = with;
        sub->event = event;
        sub->pid = pid;
        os_listeners_changed(event);
    }
    port_irq_restore(s);
    return st;
}

sys_status Sys_Subscribe_to_Event(sys_event_id event, sys_pid pid, sys_event_handler handler,
                                  sys_event_condition condition) {
    if (handler == NULL) return SYS_E_INVALID;
    condition_or_binding with = {.condition = condition};
    return subscribe(event, pid, handler, with, NULL);
}

static sys_status unsubscribe_matching(sys_event_id event, sys_pid pid, sys_event_handler handler,
                                       const sys_event_binding *binding) {
    port_irq_state_t s = port_irq_save();
    subscription *sub = find_subscription(event, pid, handler, binding);
    if (sub != NULL) unsubscribe(sub);
    port_irq_restore(s);
    return sub != NULL ? SYS_OK : SYS_E_NOT_FOUND;
}

sys_status Sys_Unsubscribe_from_Event(sys_event_id event, sys_pid pid, sys_event_handler handler) {
    /* A NULL handler would find a marked entry. */
    return handler != NULL ? unsubscribe_matching(event, pid, handler, NULL) : SYS_E_NOT_FOUND;
}

#if OS_CFG_HANDLER_CONTEXT
sys_status Sys_Subscribe_with_Context(sys_event_id event, sys_pid pid, const sys_event_binding *binding) {
    if (binding == NULL || binding->handler == NULL) return SYS_E_INVALID;
    condition_or_binding with = {.binding = binding};
    return subscribe(event, pid, bound, with, binding);
}

sys_status Sys_Unsubscribe_with_Context(sys_event_id event, sys_pid pid, const sys_event_binding *binding) {
    return binding != NULL ? unsubscribe_matching(event, pid, bound, binding) : SYS_E_NOT_FOUND;
}
#endif

void os_subscriptions_remove_thread(sys_pid pid) { remove_subscriptions(0, true, pid, false); }

#if OS_CFG_CLOCK_EVENT
bool os_event_has_listeners(sys_event_id event) {
    for (const subscription *sub = subs; sub != subs_end; sub++)
        if (sub->handler != NULL && sub->event == event) return true;
    for (const sys_tcb *t = &os.threads[1]; t != &os.threads[OS_CFG_MAX_THREADS]; t++)
        if (t->wait != NULL && t->wait->event == event) return true; /* wait: set while blocked */
    return false;
}
#endif

/* A handler must not leave a critical section open: it is closed for it. */
static OS_COLD void close_leaked_section(sys_pid pid) {
    os.lock_depth = 0;
    os_count(&os_stats.critical_leaks);
    os_fault(SYS_FAULT_CRITICAL_LEAK, pid);
}

/* A plain handler (no condition, no context) is called straight from the
 * dispatch loop, so that the loop keeps nothing for the call in saved
 * registers (9 cycles on the way to a handler, 18 on a round trip), and
 * the others through run_handler_with, out of line. With the system
 * thread alone (kilolib's programs) the one call stays: the second costs
 * 30 bytes, which their flash budget has not (docs/benchmarks.md). */
#if OS_CFG_MAX_THREADS > 1
#define PLAIN_HANDLER_APART 1
#define HANDLER_WITH_PLACE OS_COLD
#else
#define PLAIN_HANDLER_APART 0
#define HANDLER_WITH_PLACE OS_HOT
#endif

/* A port that watches which handlers run (the native mode's simulator, for
 * its "handler never called") is told of each call; the robots' ports are
 * not, and pay nothing. */
#ifndef PORT_HANDLER_CALLED
#define PORT_HANDLER_CALLED(function) ((void)0)
#endif

/* One handler call, if its condition accepts the occurrence; false to
 * unsubscribe. */
static HANDLER_WITH_PLACE bool run_handler_with(sys_event_handler handler, condition_or_binding with,
                                                sys_pid pid, const sys_event_data *data) {
#if OS_CFG_HANDLER_CONTEXT
    if (handler == bound) {
        const sys_event_binding *b = with.binding;
        return (b->condition != NULL && !b->condition(data)) ||
               (PORT_HANDLER_CALLED(b->handler), b->handler(b->context, pid, data));
    }
#endif
    return (with.condition != NULL && !with.condition(data)) ||
           (PORT_HANDLER_CALLED(handler), handler(pid, data->event, data));
}

static OS_HOT bool run_handler(sys_event_handler handler, condition_or_binding with, sys_pid pid,
                               const sys_event_data *data) {
#if PLAIN_HANDLER_APART
    bool plain = with.condition == NULL;
#if OS_CFG_HANDLER_CONTEXT
    plain = plain && handler != bound;
#endif
    if (plain) return PORT_HANDLER_CALLED(handler), handler(pid, data->event, data);
#endif
    return run_handler_with(handler, with, pid, data);
}

/* Runs in the system thread with interrupts masked; each handler runs with
 * interrupts enabled. Handlers subscribed during the dispatch wait for the
 * next occurrence. The event is read from data and the entry, not kept in
 * a register across the handler calls: one saved register fewer here and
 * in the dispatch loop this is inlined into (bench/avr_bench.py). */
void os_run_handlers(const sys_event_data *data) {
    const subscription *end = subs_end; /* later subscriptions wait for the next occurrence */
    os.handling_event = (uint8_t)(data->event + 1u);
#if OS_CFG_HANDLER_LIMIT_MS
    os_tick_look_again(); /* the watch counts every tick while handlers run */
#endif
    for (subscription *sub = subs; sub != end; sub++) {
        sys_event_handler handler = sub->handler;
        if (handler != NULL && sub->event == data->event) {
            condition_or_binding with = sub->with; /* read whole before an interrupt may unsubscribe */
#if OS_CFG_HANDLER_LIMIT_MS
            os.handler_ms = 0;
#endif
            port_irq_enable();
            bool keep = run_handler(handler, with, sub->pid, data);
            port_irq_disable();
            if (os.lock_depth != 0) close_leaked_section(sub->pid);
            /* Returning false unsubscribes. The entry is still this
             * subscription: the array is never packed while handlers run. */
            if (!keep) unsubscribe(sub);
        }
    }
    os.handling_event = 0;
}

sys_status Sys_Get_EventData(sys_event_id event, void *buffer, uint8_t capacity, uint8_t *size) {
    if (event >= OS_CFG_MAX_EVENTS || (buffer == NULL && capacity != 0)) return SYS_E_INVALID;
    port_irq_state_t s = port_irq_save();
    os_event_slot *slot = &os_events[event];
    sys_status st;
    if (slot->size == UNREGISTERED) {
        st = SYS_E_NOT_REGISTERED;
    } else if (slot->size == NOTHING_KEPT) {
        st = SYS_E_NOT_FOUND;
    } else {
        uint8_t n = slot->size < capacity ? slot->size : capacity;
        if (n != 0) memcpy(buffer, slot->data, n);
        if (size != NULL) *size = slot->size;
        st = slot->size > capacity ? SYS_E_TRUNCATED : SYS_OK;
    }
    port_irq_restore(s);
    return st;
}

sys_status Sys_Clear_EventData(sys_event_id event) {
    if (event >= OS_CFG_MAX_EVENTS) return SYS_E_INVALID;
    port_irq_state_t s = port_irq_save();
    sys_status st = SYS_E_NOT_REGISTERED;
    if (os_events[event].size != UNREGISTERED) {
        if (!os_event_queue_holds(event)) os_events[event].size = NOTHING_KEPT;
        st = SYS_OK;
    }
    port_irq_restore(s);
    return st;
}
