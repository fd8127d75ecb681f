/* kilolib programs' tests: the pools openswarm build gives a kilolib app
 * (kilolib_pools.h), so each test runs as the app would. */
#include "kilolib_pools.h"
