/* Names of status codes and faults, for logs, consoles and test failure
 * messages. */
#include "openswarm/fault.h"
#include "openswarm/types.h"

const char *Sys_Status_Name(sys_status status) {
    switch (status) {
    case SYS_OK: return "SYS_OK";
    case SYS_E_INVALID: return "SYS_E_INVALID";
    case SYS_E_NOT_REGISTERED: return "SYS_E_NOT_REGISTERED";
    case SYS_E_EXISTS: return "SYS_E_EXISTS";
    case SYS_E_POOL_FULL: return "SYS_E_POOL_FULL";
    case SYS_E_QUEUE_FULL: return "SYS_E_QUEUE_FULL";
    case SYS_E_TOO_BIG: return "SYS_E_TOO_BIG";
    case SYS_E_TIMEOUT: return "SYS_E_TIMEOUT";
    case SYS_E_CONTEXT: return "SYS_E_CONTEXT";
    case SYS_E_TRUNCATED: return "SYS_E_TRUNCATED";
    case SYS_E_NOT_FOUND: return "SYS_E_NOT_FOUND";
    default: return "SYS_E_UNKNOWN";
    }
}

const char *Sys_Fault_Name(uint8_t fault) {
    switch (fault) {
    case SYS_FAULT_STACK_OVERFLOW: return "stack overflow";
    case SYS_FAULT_CRITICAL_LEAK: return "critical section left open";
    case SYS_FAULT_CPU: return "CPU fault";
    case SYS_FAULT_HANDLER_OVERRUN: return "an event handler ran past its limit";
    default: return "fault";
    }
}
