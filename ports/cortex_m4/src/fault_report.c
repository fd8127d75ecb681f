/* Kernel faults on the board's console, so none goes unseen:
 * "kernel fault: stack overflow in thread 19". */
#include "openswarm/fault.h"
#include "openswarm/port.h"
#include "text_out.h"

static const char *fault_name(uint8_t fault) {
    switch (fault) {
    case SYS_FAULT_STACK_OVERFLOW: return "stack overflow";
    case SYS_FAULT_CRITICAL_LEAK: return "critical section left open";
    case SYS_FAULT_CPU: return "CPU fault";
    default: return "fault";
    }
}

void port_report_fault(uint8_t fault, sys_pid pid) {
    text_out("kernel fault: ");
    text_out(fault_name(fault));
    text_out(" in thread ");
    text_out_uint(pid);
    text_out("\n");
}
