/* The AVR suites' pools with the periodic 1 ms tick (no tickless idle):
 * the Kilobot port as it ran before, kept tested and measured beside it. */
#include "avr_test_config.h"
#define OS_CFG_TICKLESS 0
