/* footprint_threads2.h's kernel without the quiet tick (OS_CFG_QUIET_TICK 0):
 * every tick takes os_tick, every slice's end the general decision. The
 * difference is what the tick's shortcuts cost in flash. */
#include "footprint_threads2.h"
#define OS_CFG_QUIET_TICK 0
