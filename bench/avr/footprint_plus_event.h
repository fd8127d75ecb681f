/* footprint_base.h plus one event slot (same data arena). */
#include "footprint_base.h"
#undef OS_CFG_MAX_EVENTS
#define OS_CFG_MAX_EVENTS 7
