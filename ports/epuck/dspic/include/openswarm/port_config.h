/* e-puck (dsPIC30F6014A) port: pool sizes for 8 KB of RAM. Six threads of
 * 128 bytes (256 with the port's extra) in a 1.5 KB pool, the device
 * layer's eight events (42 bytes of values) beside the app's, proximity
 * readings (32 bytes) as the largest HAL value; about 5.5 KB are left to
 * the main (system) stack and the board. An application overrides any of
 * them (OS_CONFIG_FILE). */
#ifndef OPENSWARM_PORT_CONFIG_H
#define OPENSWARM_PORT_CONFIG_H

#ifndef OS_CFG_MAX_THREADS
#define OS_CFG_MAX_THREADS 6
#endif
#ifndef OS_CFG_STACK_BLOCK_BYTES
#define OS_CFG_STACK_BLOCK_BYTES 32
#endif
#ifndef OS_CFG_DEFAULT_STACK_BYTES
#define OS_CFG_DEFAULT_STACK_BYTES 128
#endif
#ifndef OS_CFG_STACK_POOL_BYTES
#define OS_CFG_STACK_POOL_BYTES 1536
#endif
#ifndef OS_CFG_MAX_EVENTS
#define OS_CFG_MAX_EVENTS 20
#endif
#ifndef OS_CFG_EVENT_DATA_BYTES
#define OS_CFG_EVENT_DATA_BYTES 128
#endif
#ifndef OS_CFG_MAX_SUBSCRIPTIONS
#define OS_CFG_MAX_SUBSCRIPTIONS 12
#endif
#ifndef OS_CFG_EVENT_QUEUE_BYTES
#define OS_CFG_EVENT_QUEUE_BYTES 96
#endif
#ifndef OS_CFG_MAX_DEVICES
#define OS_CFG_MAX_DEVICES 10
#endif
#ifndef OS_CFG_HAL_MAX_VALUE
#define OS_CFG_HAL_MAX_VALUE 36 /* eight proximity sensors' ambient and reflected values + a stamp */
#endif
/* The kernel's software guard sits at the bottom of each stack, where a
 * downward stack overflows; a dsPIC stack grows up, so SPLIM's trap is the
 * guard here (traps.s). With 1 the guard stays intact below the stack
 * (port_context_init starts above it) and costs 4 bytes a thread. */
#ifndef OS_CFG_STACK_CHECK
#define OS_CFG_STACK_CHECK 0
#endif

#endif
