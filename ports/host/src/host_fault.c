/* Kernel faults on standard error. A fault can be found in the tick, which
 * runs in a signal handler here, so the line is written with write(2), the
 * async-signal-safe call, not stdio. */
#include <unistd.h>

#include "openswarm/fault.h"
#include "openswarm/port.h"

void port_report_fault(uint8_t fault, sys_pid pid) {
    static const char overflow[] = "openswarm: kernel fault: stack overflow in thread ";
    static const char leak[] = "openswarm: kernel fault: critical section left open in thread ";
    char line[sizeof leak + 4];
    const char *what = fault == SYS_FAULT_STACK_OVERFLOW ? overflow : leak;
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
