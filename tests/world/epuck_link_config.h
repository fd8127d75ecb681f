/* Kernel pools for the world link's test app (epuck_link_app.c): the
 * e-puck's 8 devices and their events, one thread, one subscription. */
#define OS_CFG_MAX_THREADS 4
#define OS_CFG_STACK_POOL_BYTES 1024
#define OS_CFG_STACK_BLOCK_BYTES 32
#define OS_CFG_MAX_EVENTS 24
#define OS_CFG_EVENT_DATA_BYTES 128
#define OS_CFG_DEFAULT_EVENT_DATA 8
#define OS_CFG_MAX_SUBSCRIPTIONS 8
#define OS_CFG_EVENT_QUEUE_BYTES 128
#define OS_CFG_MAX_DEVICES 8
#define OS_CFG_HAL_MAX_VALUE 36
