/* Kernel pool sizes for the Listing 1 demo: just what it uses, as a robot
 * build would be sized. */
#define OS_CFG_MAX_THREADS 4       /* system, camera, logging, experiment timer */
#define OS_CFG_MAX_EVENTS 8        /* 4 kernel ids + camera colour + 2 motor speeds */
#define OS_CFG_MAX_SUBSCRIPTIONS 4 /* object_clustering + one per motor */
#define OS_CFG_MAX_DEVICES 3       /* camera, left and right motor */
#define OS_CFG_HAL_MAX_VALUE 2     /* a colour byte or an int16 speed */
#define OS_CFG_EVENT_DATA_BYTES 16
#define OS_CFG_EVENT_QUEUE_BYTES 32
#define OS_CFG_STACK_POOL_BYTES 512
