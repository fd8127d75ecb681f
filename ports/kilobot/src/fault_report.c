/* Kernel faults on the simulator's console (GPIOR1, which the robot
 * itself ignores), so a fault in a simulated robot is never silent:
 *   kernel fault: stack overflow in thread 19 */
#include "openswarm/fault.h"
#include "openswarm/kilobot_sim.h"
#include "openswarm/port.h"

void port_report_fault(uint8_t fault, sys_pid pid) {
    sim_puts_P(PSTR("kernel fault: "));
    if (fault == SYS_FAULT_STACK_OVERFLOW)
        sim_puts_P(PSTR("stack overflow"));
    else
        sim_puts_P(PSTR("critical section left open"));
    sim_puts_P(PSTR(" in thread "));
    if (pid >= 100u) sim_putc((char)('0' + pid / 100u));
    if (pid >= 10u) sim_putc((char)('0' + pid / 10u % 10u));
    sim_putc((char)('0' + pid % 10u));
    sim_putc('\n');
}
