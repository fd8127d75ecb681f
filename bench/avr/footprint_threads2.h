/* footprint_base.h's kernel for the app built with 2 user threads
 * (footprint_app.c, USER_THREADS 2): a slot and a default stack each. */
#include "footprint_base.h"
#undef OS_CFG_MAX_THREADS
#define OS_CFG_MAX_THREADS 3
#undef OS_CFG_STACK_POOL_BYTES
#define OS_CFG_STACK_POOL_BYTES 128
