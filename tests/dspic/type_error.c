/* A type error in port code: the 16-bit check must reject it
 * (ctest dspic.syntax_check_catches_errors). */
#include "openswarm/port.h"

void start(void);
void start(void) {
    uint16_t stack[32];
    port_context_init(stack, stack, sizeof stack, 0, 0); /* not a port_context_t * */
}
