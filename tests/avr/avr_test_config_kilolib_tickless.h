/* The kilolib test kernel with tickless idle (OS_CFG_TICKLESS 1). */
#include "avr_test_config_kilolib.h"
#define OS_CFG_TICKLESS 1
