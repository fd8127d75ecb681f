/* The AVR suites' pools with tickless idle (OS_CFG_TICKLESS 1, off by
 * default): the firmware that tests and measures it. */
#include "avr_test_config.h"
#define OS_CFG_TICKLESS 1
