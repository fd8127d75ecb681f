/* Basic types and status codes shared by every kernel header. */
#ifndef OPENSWARM_TYPES_H
#define OPENSWARM_TYPES_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "openswarm/config.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Process id: slot in the low 4 bits, reuse generation in the high 4 bits,
 * so a stale id of a reaped thread is rejected instead of hitting its
 * successor. 0 is the system thread. */
typedef uint8_t sys_pid;
#define SYS_PID_SYSTEM ((sys_pid)0)
#define SYS_PID_NONE ((sys_pid)0xFF)

typedef uint8_t sys_event_id;

/* Every call that can fail returns one of these; SYS_OK is 0, errors < 0. */
typedef int8_t sys_status;
enum {
    SYS_OK = 0,
    SYS_E_INVALID = -1,        /* bad argument or stale/unknown id */
    SYS_E_NOT_REGISTERED = -2, /* the event is not registered */
    SYS_E_EXISTS = -3,         /* already registered / subscribed */
    SYS_E_POOL_FULL = -4,      /* a static pool has no free entry */
    SYS_E_QUEUE_FULL = -5,     /* the event queue has no room */
    SYS_E_TOO_BIG = -6,        /* data larger than the event's capacity */
    SYS_E_TIMEOUT = -7,        /* a wait ran out of time */
    SYS_E_CONTEXT = -8,        /* not allowed here (interrupt, handler) */
    SYS_E_TRUNCATED = -9,      /* data did not fit the caller's buffer */
    SYS_E_NOT_FOUND = -10      /* no such subscription / device */
};

/* Short name of a status, e.g. "SYS_E_QUEUE_FULL"; for logs and tests. */
const char *Sys_Status_Name(sys_status status);

#ifdef __cplusplus
}
#endif

#endif
