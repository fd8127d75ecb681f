/* The host suite's pools without the kernel's optional features (config.h):
 * the whole suite runs again on this kernel, to show what going without
 * them changes (test_faults.cpp, test_time.cpp) and that nothing else does. */
#include "test_config.h"
#define OS_CFG_STACK_CHECK 0
#define OS_CFG_CLOCK_EVENT 0
/* Not a feature but a shortcut: without it every tick takes os_tick, and
 * the end of a slice the general decision. */
#define OS_CFG_QUIET_TICK 0
