/* Kernel faults on the console, so none goes unseen:
 * "kernel fault: stack overflow in thread 19". */
#include "dspic_port.h"
#include "openswarm/fault.h"
#include "openswarm/port.h"

void port_report_fault(uint8_t fault, sys_pid pid) {
    dspic_console_print("kernel fault: ");
    dspic_console_print(Sys_Fault_Name(fault));
    dspic_console_print(" in thread ");
    dspic_console_print_uint(pid);
    dspic_console_print("\n");
}
