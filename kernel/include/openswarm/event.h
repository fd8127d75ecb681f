/* Events: registration, handler subscription, sending, and waiting.
 *
 * Event ids are small integers below OS_CFG_MAX_EVENTS; the kernel's own
 * events take the ids below SYS_EVENT_FIRST_FREE. Each registered event
 * keeps the data sent with it last (the paper's d_i), up to the capacity
 * given when it was registered.
 *
 * Handlers run to completion in the system thread, between two scheduled
 * threads, in the order the events were sent. An event sent by a thread is
 * dispatched before Sys_Send_Event returns (unless the thread is inside a
 * critical section); one sent by an interrupt is dispatched as soon as the
 * interrupt returns. */
#ifndef OPENSWARM_EVENT_H
#define OPENSWARM_EVENT_H

#include "openswarm/types.h"
#include "openswarm/port_arch.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Sent every 1 ms tick while anybody listens; data: uint32_t system time.
 * Left out by OS_CFG_CLOCK_EVENT 0 (config.h). */
#define SYS_EVENT_1MS_TIMER ((sys_event_id)0)
/* Sent when the kernel detects a fault; data: sys_fault_info. */
#define SYS_EVENT_FAULT ((sys_event_id)1)
/* Reserved for ports: the robot's own device events (PORT_EVENT_COUNT of
 * them, from port_arch.h) start here; applications' ids after them. */
#define SYS_EVENT_PORT_FIRST ((sys_event_id)2)
#define SYS_EVENT_FIRST_FREE ((sys_event_id)(SYS_EVENT_PORT_FIRST + PORT_EVENT_COUNT))

/* The data of one occurrence of an event, as handlers and conditions see it. */
typedef struct sys_event_data {
    const void *value;
    uint8_t size;
    sys_event_id event;
} sys_event_data;

/* A handler runs for every occurrence (or every one its condition accepts).
 * pid is the subscribing thread. Return false to unsubscribe. */
typedef bool (*sys_event_handler)(sys_pid pid, sys_event_id event, const sys_event_data *data);
/* A condition decides whether an occurrence wakes a waiter or runs a handler.
 * Conditions of waits run in the system thread with interrupts masked, so
 * keep them to a few instructions (a counter, a comparison). */
typedef bool (*sys_event_condition)(const sys_event_data *data);

/* Register with OS_CFG_DEFAULT_EVENT_DATA bytes of data capacity. */
sys_status Sys_Register_Event(sys_event_id event);
/* Register with an explicit data capacity (0..SYS_EVENT_DATA_MAX bytes). */
#define SYS_EVENT_DATA_MAX 253
sys_status Sys_Register_Event_Sized(sys_event_id event, uint8_t capacity);
/* Unregister: subscriptions are dropped, waiters woken with
 * SYS_E_NOT_REGISTERED. Occurrences still queued are discarded and counted
 * (sys_stats.events_discarded) unless the event is registered again before
 * they are dispatched, in which case the new registration receives them. */
sys_status Sys_Unregister_Event(sys_event_id event);
bool Sys_IsEventRegistered(sys_event_id event);

/* Subscribe handler for thread pid (0 = the system thread). A handler is
 * subscribed at most once per (event, thread): a second call is SYS_E_EXISTS.
 * condition may be NULL. */
sys_status Sys_Subscribe_to_Event(sys_event_id event, sys_pid pid, sys_event_handler handler,
                                  sys_event_condition condition);
sys_status Sys_Unsubscribe_from_Event(sys_event_id event, sys_pid pid, sys_event_handler handler);

/* A handler with a context: the binding gives the function, the pointer it
 * gets back on every call (an object, a table entry) and an optional
 * condition. The binding must outlive the subscription (a static, or a
 * member of a long-lived object); one binding subscribes once per (event,
 * thread). Left out by OS_CFG_HANDLER_CONTEXT 0 (config.h). */
typedef bool (*sys_event_context_handler)(void *context, sys_pid pid, const sys_event_data *data);
typedef struct sys_event_binding {
    sys_event_context_handler handler;
    void *context;
    sys_event_condition condition; /* may be NULL */
} sys_event_binding;
sys_status Sys_Subscribe_with_Context(sys_event_id event, sys_pid pid, const sys_event_binding *binding);
sys_status Sys_Unsubscribe_with_Context(sys_event_id event, sys_pid pid, const sys_event_binding *binding);

/* Queue an occurrence with a copy of size bytes of data. Never blocks;
 * callable from threads, handlers and interrupts. */
sys_status Sys_Send_Event(sys_event_id event, const void *data, uint8_t size);
/* Send a 16-bit integer (the paper's motor-speed style events). */
sys_status Sys_Send_IntEvent(sys_event_id event, int16_t value);

/* Block the calling thread until the next occurrence of event (for which
 * condition returns true) and copy its data into buffer. *size (may be NULL)
 * receives the occurrence's full size; SYS_E_TRUNCATED if it exceeded
 * capacity. Threads only: SYS_E_CONTEXT from handlers and interrupts. */
sys_status Sys_Wait_for_Event(sys_event_id event, void *buffer, uint8_t capacity, uint8_t *size);
sys_status Sys_Wait_for_Condition(sys_event_id event, sys_event_condition condition, void *buffer,
                                  uint8_t capacity, uint8_t *size);
/* The same with a timeout in ms: SYS_E_TIMEOUT if nothing came in time. */
sys_status Sys_Wait_for_Event_Timeout(sys_event_id event, uint32_t timeout_ms, void *buffer,
                                      uint8_t capacity, uint8_t *size);
sys_status Sys_Wait_for_Condition_Timeout(sys_event_id event, sys_event_condition condition,
                                          uint32_t timeout_ms, void *buffer, uint8_t capacity,
                                          uint8_t *size);

/* Copy the data kept from the last dispatched occurrence (or from one sent
 * to an empty queue, which is kept at once). SYS_E_NOT_FOUND if none was
 * kept (never sent, or cleared). */
sys_status Sys_Get_EventData(sys_event_id event, void *buffer, uint8_t capacity, uint8_t *size);
/* Forget the kept data of event (not an occurrence kept at once and not
 * yet dispatched: its handlers will read it). */
sys_status Sys_Clear_EventData(sys_event_id event);

#ifdef __cplusplus
}
#endif

#endif
