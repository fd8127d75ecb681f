/* footprint_base.h plus one thread slot (same stack pool). */
#include "footprint_base.h"
#undef OS_CFG_MAX_THREADS
#define OS_CFG_MAX_THREADS 3
