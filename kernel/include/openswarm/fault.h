/* Faults and resource counters: nothing the kernel refuses or detects goes
 * unreported. Every failed allocation or full queue returns an error to the
 * caller and increments one of these counters, which stop at 65535 rather
 * than wrap to 0. */
#ifndef OPENSWARM_FAULT_H
#define OPENSWARM_FAULT_H

#include "openswarm/types.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum sys_fault {
    SYS_FAULT_STACK_OVERFLOW = 1, /* a thread's stack guard was overwritten (OS_CFG_STACK_CHECK) */
    SYS_FAULT_CRITICAL_LEAK,      /* a thread ended inside a critical section */
    SYS_FAULT_CPU,                /* the CPU trapped in a thread (bad address, undefined
                                     instruction, division by zero): the thread was ended */
    SYS_FAULT_HANDLER_OVERRUN     /* an event handler ran past OS_CFG_HANDLER_LIMIT_MS
                                     (reported once, with SYS_PID_SYSTEM; it runs on) */
} sys_fault;

/* A fault as a port's console names it: "stack overflow", ... ("fault" for
 * a value it does not know). */
const char *Sys_Fault_Name(uint8_t fault);

/* Data of SYS_EVENT_FAULT. */
typedef struct sys_fault_info {
    uint8_t fault; /* sys_fault */
    sys_pid pid;
} sys_fault_info;

typedef struct sys_stats {
    uint16_t process_pool_full;      /* no free thread slot */
    uint16_t stack_pool_full;        /* no room for a stack */
    uint16_t event_data_full;        /* no room for an event's data */
    uint16_t subscription_pool_full; /* no free subscription */
    uint16_t event_queue_full;       /* a send found the queue full */
    uint16_t device_table_full;      /* no free HAL device slot */
    uint16_t events_discarded;       /* queued occurrences of an event unregistered before dispatch */
    uint16_t stack_overflows;
    uint16_t critical_leaks;
    uint16_t cpu_faults;             /* threads ended by a CPU trap (ports that catch them) */
    uint16_t handler_overruns;       /* handlers that ran past OS_CFG_HANDLER_LIMIT_MS */
    uint16_t subscriptions_refused;  /* subscriptions to an event not registered (yet) */
    uint8_t event_queue_peak;        /* most bytes ever queued */
} sys_stats;

void Sys_Get_Stats(sys_stats *stats);

/* Called (in the kernel, interrupts off) when a fault is detected, before
 * SYS_EVENT_FAULT is sent. Keep it short. NULL removes it. */
typedef void (*sys_fault_hook)(sys_fault fault, sys_pid pid);
void Sys_Set_FaultHook(sys_fault_hook hook);

#ifdef __cplusplus
}
#endif

#endif
