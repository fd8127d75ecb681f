/* Kernel faults to the simulator (three writes to GPIOR1, which the robot
 * itself ignores): it prints them, so a fault in a simulated robot is never
 * silent, and the firmware carries no message text. */
#include "openswarm/kilobot_sim.h"
#include "openswarm/port.h"

void port_report_fault(uint8_t fault, sys_pid pid) { sim_fault(fault, pid); }
