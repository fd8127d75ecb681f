/* The Cortex-M4 port's pool sizes for an STM32F4's 128 KB of SRAM (the
 * e-puck2's STM32F407 has 192 KB with its CCM; QEMU's netduinoplus2 has
 * the 128). Generous next to the Kilobot's: 16 threads of 1 KB, room for
 * camera-sized processors' values. An application overrides any of them
 * (OS_CONFIG_FILE). Apart from port_config.h so that the e-puck in the
 * world simulator (ports/epuck/host) takes the very same sizes. */
#ifndef OPENSWARM_CORTEX_M4_POOLS_H
#define OPENSWARM_CORTEX_M4_POOLS_H

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
