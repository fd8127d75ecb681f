/* Kilobot port: pool sizes that fit 2 KB of RAM with the robot's devices
 * (LED, motors, IR: 16-byte values; light, voltage, temperature when
 * kilobot_sensors_init registers them: 2-byte values) and a few threads,
 * leaving about 900 bytes to the main stack. A classic kilolib program,
 * which needs no thread, gets kilolib_pools.h's instead. An application
 * overrides any of them (OS_CONFIG_FILE). */
#ifndef OPENSWARM_PORT_CONFIG_H
#define OPENSWARM_PORT_CONFIG_H

/* Tickless idle stays off by default for now: with it, fewer of 100
 * disperse robots crowded in one IR range hear a close neighbour in 5 s
 * (world.hundred_robots: 58 against 82; docs/architecture.md). */
#ifndef OS_CFG_TICKLESS
#define OS_CFG_TICKLESS 0
#endif
#ifndef OS_CFG_MAX_THREADS
#define OS_CFG_MAX_THREADS 4
#endif
#ifndef OS_CFG_STACK_BLOCK_BYTES
#define OS_CFG_STACK_BLOCK_BYTES 16
#endif
#ifndef OS_CFG_DEFAULT_STACK_BYTES
#define OS_CFG_DEFAULT_STACK_BYTES 96
#endif
#ifndef OS_CFG_STACK_POOL_BYTES
#define OS_CFG_STACK_POOL_BYTES 448
#endif
#ifndef OS_CFG_MAX_EVENTS
#define OS_CFG_MAX_EVENTS 14
#endif
#ifndef OS_CFG_EVENT_DATA_BYTES
#define OS_CFG_EVENT_DATA_BYTES 96
#endif
#ifndef OS_CFG_MAX_SUBSCRIPTIONS
#define OS_CFG_MAX_SUBSCRIPTIONS 6
#endif
#ifndef OS_CFG_EVENT_QUEUE_BYTES
#define OS_CFG_EVENT_QUEUE_BYTES 48
#endif
#ifndef OS_CFG_MAX_DEVICES
#define OS_CFG_MAX_DEVICES 6
#endif
#ifndef OS_CFG_HAL_MAX_VALUE
#define OS_CFG_HAL_MAX_VALUE 17 /* an IR reception: frame, two gains, distance */
#endif

#endif
