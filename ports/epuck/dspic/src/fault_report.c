/* Kernel faults on the console, so none goes unseen:
 * "kernel fault: stack overflow in thread 19". */
#include "dspic_port.h"
#include "openswarm/fault.h"
#include "openswarm/port.h"

static const char *fault_name(uint8_t fault) {
    switch (fault) {
    case SYS_FAULT_STACK_OVERFLOW: return "stack overflow";
    case SYS_FAULT_CRITICAL_LEAK: return "critical section left open";
    case SYS_FAULT_CPU: return "CPU fault";
    case SYS_FAULT_HANDLER_OVERRUN: return "an event handler ran past its limit";
    default: return "fault";
    }
}

void port_report_fault(uint8_t fault, sys_pid pid) {
    dspic_console_print("kernel fault: ");
    dspic_console_print(fault_name(fault));
    dspic_console_print(" in thread ");
    dspic_console_print_uint(pid);
    dspic_console_print("\n");
}
