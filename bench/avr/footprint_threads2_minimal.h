/* footprint_threads2.h's kernel with neither the optional features
 * (footprint_minimal.h's list) nor the quiet tick: the smallest kernel the
 * app with 2 user threads can have, its threads, events, waits, handlers
 * and policies all kept. */
#include "footprint_threads2_loud.h"
#define OS_CFG_STACK_CHECK 0
#define OS_CFG_CLOCK_EVENT 0
#define OS_CFG_HANDLER_LIMIT_MS 0
#define OS_CFG_HANDLER_CONTEXT 0
