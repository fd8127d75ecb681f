/* footprint_base.h's kernel without the features a robot may go without
 * (kernel/include/openswarm/config.h): no stack guard, no clock event, no
 * watch on handlers that run too long. */
#include "footprint_base.h"
#define OS_CFG_STACK_CHECK 0
#define OS_CFG_CLOCK_EVENT 0
#define OS_CFG_HANDLER_LIMIT_MS 0
