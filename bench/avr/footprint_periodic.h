/* footprint_base.h's kernel with the periodic tick only (no tickless
 * idle): the difference is tickless idle's flash and RAM. */
#include "footprint_base.h"
#define OS_CFG_TICKLESS 0
