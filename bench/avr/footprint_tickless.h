/* footprint_base.h's kernel with tickless idle (OS_CFG_TICKLESS 1, off
 * by default): the difference is tickless idle's flash and RAM. */
#include "footprint_base.h"
#define OS_CFG_TICKLESS 1
