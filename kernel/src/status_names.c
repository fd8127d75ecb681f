/* Names of status codes, for logs and test failure messages. */
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
