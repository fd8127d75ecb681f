/*
 * Build-time sizes of every kernel pool.
 *
 * The kernel never allocates at run time: each table below is a static
 * array whose size is fixed here. An application overrides any value by
 * defining OS_CONFIG_FILE (e.g. -DOS_CONFIG_FILE='"app_config.h"'); the
 * openswarm tool generates that header from openswarm.json. Next come the
 * port's defaults (openswarm/port_config.h: what fits the robot), then the
 * generic ones below.
 */
#ifndef OPENSWARM_CONFIG_H
#define OPENSWARM_CONFIG_H

#ifdef OS_CONFIG_FILE
#include OS_CONFIG_FILE
#endif
#include "openswarm/port_config.h"

/* Features a robot may go without, for flash (docs/benchmarks.md has how
 * much each costs). Each is 1 (on, the default) or 0. */

/* Stack overflow detection: a 4-byte guard pattern at the bottom of every
 * thread stack, compared at every scheduling decision a thread makes and at
 * every tick that leads to one (at least once a slice); a thread that overwrote it is stopped and reported
 * (SYS_FAULT_STACK_OVERFLOW, sys_stats.stack_overflows). With 0 stacks have
 * no guard and an overflow goes unnoticed, corrupting whatever lies below. */
#ifndef OS_CFG_STACK_CHECK
#define OS_CFG_STACK_CHECK 1
#endif

/* The clock event: SYS_EVENT_1MS_TIMER, registered by Sys_Init_Kernel and
 * sent at every tick while a handler or waiter listens. With 0 there is no
 * clock event: registering SYS_EVENT_1MS_TIMER fails with SYS_E_INVALID, so
 * subscribing to it or waiting for it fails with SYS_E_NOT_REGISTERED. Time
 * goes on as before for Sys_Sleep, timeouts, time slices and
 * Sys_Get_SystemTime. */
#ifndef OS_CFG_CLOCK_EVENT
#define OS_CFG_CLOCK_EVENT 1
#endif

/* Tickless idle: when every thread waits and no timeout is near, the
 * system thread asks the port to sleep until the next deadline (or any
 * interrupt) with the tick stopped, and the ticks that passed are credited
 * at once when it wakes: time, timeouts and slices stay exact. Only while
 * the clock event has no listener; a port without tickless idle (its
 * port_arch.h does not define PORT_TICKLESS_IDLE) keeps the periodic tick,
 * and asking it for tickless idle is a build error. Off by default (the
 * Kilobot has it off too); the Cortex-M4's port_config.h turns it on. */
#ifndef OS_CFG_TICKLESS
#define OS_CFG_TICKLESS 0
#endif

/* The quiet tick: most ticks need nothing but the time and the slice's
 * count, so a countdown of the coming ticks that need no more lets them
 * return at once (os_tick_quiet: 102 cycles a tick on the Kilobot instead
 * of 180), and the tick that ends a slice with a plain rotation rotates at
 * once (340 cycles to the next thread instead of 495); together about 520
 * bytes of flash and 1 of RAM. On wherever threads
 * run; with the system thread alone (kilolib's programs) off by default:
 * no slice to count, and kilolib's clock hook takes every tick the full
 * way anyway. */
#ifndef OS_CFG_QUIET_TICK
#define OS_CFG_QUIET_TICK (OS_CFG_MAX_THREADS > 1)
#endif

/* Threads, including the system thread (pid 0). At most 16; 1 leaves the
 * system thread alone (its program, Sys_Run_SystemProgram, and handlers). */
#ifndef OS_CFG_MAX_THREADS
#define OS_CFG_MAX_THREADS 8
#endif

/* Stacks are carved from the pool in blocks of this many bytes. */
#ifndef OS_CFG_STACK_BLOCK_BYTES
#define OS_CFG_STACK_BLOCK_BYTES 32
#endif

/* Stack size of Sys_Start_Process (the paper's default: 128 B). */
#ifndef OS_CFG_DEFAULT_STACK_BYTES
#define OS_CFG_DEFAULT_STACK_BYTES 128
#endif

/* Bytes shared by all thread stacks (before the port's per-stack extra and
 * the 4-byte guard, if OS_CFG_STACK_CHECK). By default every thread fits
 * at the default size. */
#ifndef OS_CFG_STACK_POOL_BYTES
#define OS_CFG_STACK_POOL_BYTES \
    ((OS_CFG_MAX_THREADS - 1) * \
     ((OS_CFG_DEFAULT_STACK_BYTES + 4 * OS_CFG_STACK_CHECK + OS_CFG_STACK_BLOCK_BYTES - 1) / \
      OS_CFG_STACK_BLOCK_BYTES) * \
     OS_CFG_STACK_BLOCK_BYTES)
#endif

/* Event ids are 0 .. OS_CFG_MAX_EVENTS-1. At most 255. */
#ifndef OS_CFG_MAX_EVENTS
#define OS_CFG_MAX_EVENTS 16
#endif

/* Bytes that hold the last data of every registered event (the d_i). */
#ifndef OS_CFG_EVENT_DATA_BYTES
#define OS_CFG_EVENT_DATA_BYTES 64
#endif

/* Data capacity of an event registered with Sys_Register_Event. */
#ifndef OS_CFG_DEFAULT_EVENT_DATA
#define OS_CFG_DEFAULT_EVENT_DATA 4
#endif

/* Handler subscriptions, over all events and threads. */
#ifndef OS_CFG_MAX_SUBSCRIPTIONS
#define OS_CFG_MAX_SUBSCRIPTIONS 8
#endif

/* Bytes of the queue of sent, not yet dispatched events (2 B header each). */
#ifndef OS_CFG_EVENT_QUEUE_BYTES
#define OS_CFG_EVENT_QUEUE_BYTES 64
#endif

/* HAL devices. */
#ifndef OS_CFG_MAX_DEVICES
#define OS_CFG_MAX_DEVICES 4
#endif

/* Largest value a HAL processor may produce, in bytes. */
#ifndef OS_CFG_HAL_MAX_VALUE
#define OS_CFG_HAL_MAX_VALUE 16
#endif

/* An event handler that runs longer than this (ms) without returning is
 * reported once as a kernel fault (SYS_FAULT_HANDLER_OVERRUN): handlers run
 * to completion on the system thread, so one that never returns freezes
 * every other handler and the threads that wait for them. 0: never. */
#ifndef OS_CFG_HANDLER_LIMIT_MS
#define OS_CFG_HANDLER_LIMIT_MS 1000
#endif
#if OS_CFG_HANDLER_LIMIT_MS > 65535
#error "OS_CFG_HANDLER_LIMIT_MS must fit in 16 bits (at most 65535 ms)"
#endif

/* Handlers with a context pointer (Sys_Subscribe_with_Context): a
 * comparison per handler call in the dispatch. 0 leaves them out. */
#ifndef OS_CFG_HANDLER_CONTEXT
#define OS_CFG_HANDLER_CONTEXT 1
#endif

/* Default time slice of the round-robin scheduler, in ms (= ticks). */
#ifndef OS_CFG_TIME_SLICE_MS
#define OS_CFG_TIME_SLICE_MS 10
#endif

#if (OS_CFG_STACK_CHECK != 0 && OS_CFG_STACK_CHECK != 1) || \
    (OS_CFG_CLOCK_EVENT != 0 && OS_CFG_CLOCK_EVENT != 1) || \
    (OS_CFG_HANDLER_CONTEXT != 0 && OS_CFG_HANDLER_CONTEXT != 1) || \
    (OS_CFG_TICKLESS != 0 && OS_CFG_TICKLESS != 1) || (OS_CFG_QUIET_TICK != 0 && OS_CFG_QUIET_TICK != 1)
#error "OS_CFG_STACK_CHECK, OS_CFG_CLOCK_EVENT, OS_CFG_HANDLER_CONTEXT, OS_CFG_TICKLESS and OS_CFG_QUIET_TICK must be 0 or 1"
#endif
#if OS_CFG_MAX_THREADS < 1 || OS_CFG_MAX_THREADS > 16
#error "OS_CFG_MAX_THREADS must be 1..16 (1: the system thread alone; pids keep the slot in 4 bits)"
#endif
#if OS_CFG_MAX_EVENTS < 2 || OS_CFG_MAX_EVENTS > 255
#error "OS_CFG_MAX_EVENTS must be 2..255 (the kernel's own events use ids 0 and 1)"
#endif
#if OS_CFG_STACK_POOL_BYTES % OS_CFG_STACK_BLOCK_BYTES != 0
#error "OS_CFG_STACK_POOL_BYTES must be a multiple of OS_CFG_STACK_BLOCK_BYTES"
#endif
#if OS_CFG_EVENT_QUEUE_BYTES > 255
#error "OS_CFG_EVENT_QUEUE_BYTES must fit in 8 bits"
#endif

#endif
