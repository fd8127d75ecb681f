/* Kernel pools for the firmware suites on the Cortex-M4: the Kilobot
 * suite's (its expectations, such as the queue's capacity, are in those
 * numbers), with room for the e-puck board's 16 device event ids where
 * the Kilobot reserves 8. */
#include "../avr/avr_test_config.h"
#undef OS_CFG_MAX_EVENTS
#define OS_CFG_MAX_EVENTS (14 - 8 + 16)
