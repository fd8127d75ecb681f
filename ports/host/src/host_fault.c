/* Kernel faults on standard error. A fault can be found in the tick, which
 * runs in a signal handler here, so the line is written with write(2), the
 * async-signal-safe call, not stdio. */
#include <unistd.h>

#include "openswarm/fault.h"
#include "openswarm/port.h"

static const char *fault_text(uint8_t fault) {
    switch (fault) {
    case SYS_FAULT_STACK_OVERFLOW: return "openswarm: kernel fault: stack overflow in thread ";
    case SYS_FAULT_CRITICAL_LEAK: return "openswarm: kernel fault: critical section left open in thread ";
    case SYS_FAULT_HANDLER_OVERRUN: return "openswarm: kernel fault: an event handler ran past its limit in thread ";
    default: return "openswarm: kernel fault in thread ";
    }
}

void port_report_fault(uint8_t fault, sys_pid pid) {
    char line[96];
    const char *what = fault_text(fault);
    size_t n = 0;
    while (what[n] != '\0') {
        line[n] = what[n];
        n++;
    }
    if (pid >= 100u) line[n++] = (char)('0' + pid / 100u);
    if (pid >= 10u) line[n++] = (char)('0' + pid / 10u % 10u);
    line[n++] = (char)('0' + pid % 10u);
    line[n++] = '\n';
    ssize_t ignored = write(STDERR_FILENO, line, n); /* nothing to do if stderr is gone */
    (void)ignored;
}
