/* The smallest useful kernel: the system thread and one user thread, the
 * kernel's own two events, one subscription, a 16-byte queue. */
#define OS_CFG_MAX_THREADS 2
#define OS_CFG_STACK_POOL_BYTES 64
#define OS_CFG_STACK_BLOCK_BYTES 16
#define OS_CFG_DEFAULT_STACK_BYTES 48
#define OS_CFG_MAX_EVENTS 6
#define OS_CFG_EVENT_DATA_BYTES 6
#define OS_CFG_MAX_SUBSCRIPTIONS 1
#define OS_CFG_EVENT_QUEUE_BYTES 16
#define OS_CFG_MAX_DEVICES 1
#define OS_CFG_HAL_MAX_VALUE 4
