/* The system thread, up to 4 user threads and the control thread that ends
 * each phase, at the Kilobot's default stack size (96 bytes each). */
#define OS_CFG_MAX_THREADS 6
#define OS_CFG_MAX_EVENTS 11
#define OS_CFG_DEFAULT_STACK_BYTES 96
#define OS_CFG_STACK_BLOCK_BYTES 16
#define OS_CFG_STACK_POOL_BYTES 560
