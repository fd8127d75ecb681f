/* cycles_config.h's kernel without the features a robot may go without
 * (as footprint_minimal.h): what the optional features cost on each path
 * the cycle firmware measures. */
#include "cycles_config.h"
#define OS_CFG_STACK_CHECK 0
#define OS_CFG_CLOCK_EVENT 0
#define OS_CFG_HANDLER_LIMIT_MS 0
#define OS_CFG_HANDLER_CONTEXT 0
