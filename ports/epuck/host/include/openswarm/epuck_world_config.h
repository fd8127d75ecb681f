/* The e-puck in the world simulator (board epuck_world on the host port):
 * the e-puck2's pool sizes (ports/cortex_m4's port_config.h), so that an
 * app and the configuration `openswarm build` generates for the e-puck2
 * behave as on the robot. An application overrides any of them
 * (OS_CONFIG_FILE). */
#ifndef OPENSWARM_EPUCK_WORLD_CONFIG_H
#define OPENSWARM_EPUCK_WORLD_CONFIG_H

#ifndef OS_CFG_MAX_THREADS
#define OS_CFG_MAX_THREADS 16
#endif
#ifndef OS_CFG_STACK_BLOCK_BYTES
#define OS_CFG_STACK_BLOCK_BYTES 64
#endif
#ifndef OS_CFG_DEFAULT_STACK_BYTES
#define OS_CFG_DEFAULT_STACK_BYTES 1024
#endif
#ifndef OS_CFG_STACK_POOL_BYTES
#define OS_CFG_STACK_POOL_BYTES 16384
#endif
#ifndef OS_CFG_MAX_EVENTS
#define OS_CFG_MAX_EVENTS 48
#endif
#ifndef OS_CFG_EVENT_DATA_BYTES
#define OS_CFG_EVENT_DATA_BYTES 1024
#endif
#ifndef OS_CFG_MAX_SUBSCRIPTIONS
#define OS_CFG_MAX_SUBSCRIPTIONS 32
#endif
#ifndef OS_CFG_EVENT_QUEUE_BYTES
#define OS_CFG_EVENT_QUEUE_BYTES 255
#endif
#ifndef OS_CFG_MAX_DEVICES
#define OS_CFG_MAX_DEVICES 16
#endif
#ifndef OS_CFG_HAL_MAX_VALUE
#define OS_CFG_HAL_MAX_VALUE 36 /* eight proximity sensors' ambient and reflected values + a stamp */
#endif

#endif
