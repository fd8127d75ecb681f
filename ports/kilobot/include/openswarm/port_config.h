/* Kilobot port: pool sizes that fit 2 KB of RAM with the robot's devices
 * (LED 1 byte, motors 2, IR 17 in and 10 out; light, voltage, temperature
 * when kilobot_sensors_init registers them: 2 bytes each) and a few
 * threads, leaving about 900 bytes to the main stack. A classic kilolib program,
 * which needs no thread, gets kilolib_pools.h's instead. An application
 * overrides any of them (OS_CONFIG_FILE). */
#ifndef OPENSWARM_PORT_CONFIG_H
#define OPENSWARM_PORT_CONFIG_H

/* Tickless idle is off by default: about 830 bytes of flash (more than a
 * classic kilolib program's budget has), and an interrupt out of a sleep
 * served about 110 cycles later (docs/architecture.md, "Tickless idle"). */
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
#define OS_CFG_EVENT_DATA_BYTES 64 /* the kernel's and the port's 43, and 21 for the app's */
#endif
#ifndef OS_CFG_MAX_SUBSCRIPTIONS
#define OS_CFG_MAX_SUBSCRIPTIONS 6
#endif
/* Four IR receptions (19 bytes each with the header) and a call: a robot in
 * a crowd hears frames back to back, each 4.4 ms with interrupts masked,
 * and the gaps between them can be too short to dispatch one; two (48
 * bytes) refused about 1 frame in 80 with 9 robots in range of each other
 * (world.ir_crowd). */
#ifndef OS_CFG_EVENT_QUEUE_BYTES
#define OS_CFG_EVENT_QUEUE_BYTES 80
#endif
#ifndef OS_CFG_MAX_DEVICES
#define OS_CFG_MAX_DEVICES 6
#endif
#ifndef OS_CFG_HAL_MAX_VALUE
#define OS_CFG_HAL_MAX_VALUE 17 /* an IR reception: frame, two gains, distance */
#endif

#endif
