/* Kernel pools for a kilolib program (openswarm build includes this in the
 * configuration it generates for an app that includes kilolib.h): setup()
 * and loop() run on the system thread, so nothing needs a thread of its
 * own. What the robot registers, and no more: the kernel's events, the
 * port's 8 ids (LED, motors and IR registered at their values' sizes,
 * kilolib's calls at 1); their 5 subscriptions (a handler for each
 * output device, kilolib's message delivery and calls); the LED, motors
 * and IR devices. A setting the app's configuration gives (openswarm.json's
 * "kernel") comes first and wins. */
#ifndef KILOLIB_POOLS_H
#define KILOLIB_POOLS_H

#ifndef OS_CFG_MAX_THREADS
#define OS_CFG_MAX_THREADS 1 /* the system thread: the program and handlers */
#endif
#ifndef OS_CFG_STACK_POOL_BYTES
#define OS_CFG_STACK_POOL_BYTES 0
#endif
#ifndef OS_CFG_STACK_CHECK
#define OS_CFG_STACK_CHECK 0 /* no thread stack to guard (the main stack's check stays) */
#endif
#ifndef OS_CFG_CLOCK_EVENT
#define OS_CFG_CLOCK_EVENT 0 /* kilolib counts kilo_ticks from the port's clock hook */
#endif
#ifndef OS_CFG_HANDLER_CONTEXT
#define OS_CFG_HANDLER_CONTEXT 0
#endif
#ifndef OS_CFG_MAX_EVENTS
#define OS_CFG_MAX_EVENTS 10 /* the kernel's 2 and the port's 8 */
#endif
#ifndef OS_CFG_EVENT_DATA_BYTES
#define OS_CFG_EVENT_DATA_BYTES 33 /* the fault event 2, the devices' events 1 + 2 + 17 + 10, the calls 1 */
#endif
#ifndef OS_CFG_MAX_SUBSCRIPTIONS
#define OS_CFG_MAX_SUBSCRIPTIONS 5
#endif
#ifndef OS_CFG_MAX_DEVICES
#define OS_CFG_MAX_DEVICES 3
#endif

#endif
