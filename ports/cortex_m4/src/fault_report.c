/* Kernel faults on the board's console, so none goes unseen:
 * "kernel fault: stack overflow in thread 19". */
#include "openswarm/cortex_m4.h"
#include "openswarm/fault.h"
#include "openswarm/port.h"

void port_report_fault(uint8_t fault, sys_pid pid) {
    cortex_m4_print("kernel fault: ");
    cortex_m4_print(Sys_Fault_Name(fault));
    cortex_m4_print(" in thread ");
    cortex_m4_print_uint(pid);
    cortex_m4_print("\n");
}
