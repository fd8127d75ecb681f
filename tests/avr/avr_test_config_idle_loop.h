/* The kilolib test kernel with kilolib's idle loop (KILOLIB_IDLE_LOOP). */
#include "avr_test_config_kilolib.h"
#define KILOLIB_IDLE_LOOP 1
