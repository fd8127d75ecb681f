/* footprint_base.h plus one thread slot (same stack pool). */
#define OS_CFG_MAX_THREADS 3
#define OS_CFG_STACK_POOL_BYTES 64
#define OS_CFG_STACK_BLOCK_BYTES 16
#define OS_CFG_DEFAULT_STACK_BYTES 48
#define OS_CFG_MAX_EVENTS 6
#define OS_CFG_EVENT_DATA_BYTES 6
#define OS_CFG_MAX_SUBSCRIPTIONS 1
#define OS_CFG_EVENT_QUEUE_BYTES 16
#define OS_CFG_MAX_DEVICES 1
#define OS_CFG_HAL_MAX_VALUE 4
