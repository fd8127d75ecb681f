/* Kernel pools for the e-puck device layer's host tests: the e-puck's 8
 * devices and their events (PORT_EVENT_COUNT is given on the command line,
 * as the e-puck ports reserve 16 ids). */
#define OS_CFG_MAX_THREADS 6
#define OS_CFG_STACK_POOL_BYTES 2048
#define OS_CFG_STACK_BLOCK_BYTES 32
#define OS_CFG_MAX_EVENTS 24
#define OS_CFG_EVENT_DATA_BYTES 128
#define OS_CFG_DEFAULT_EVENT_DATA 8
#define OS_CFG_MAX_SUBSCRIPTIONS 12
#define OS_CFG_EVENT_QUEUE_BYTES 128
#define OS_CFG_MAX_DEVICES 8
#define OS_CFG_HAL_MAX_VALUE 36
