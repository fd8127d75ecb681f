/* System time: a 1 ms tick drives time slices, timeouts and the
 * SYS_EVENT_1MS_TIMER clock event. */
#ifndef OPENSWARM_SYSTEM_TIME_H
#define OPENSWARM_SYSTEM_TIME_H

#include "openswarm/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Milliseconds since Sys_Start_Kernel (wraps after 49.7 days). */
uint32_t Sys_Get_SystemTime(void);

/* Block the calling thread for ms milliseconds. */
sys_status Sys_Sleep(uint32_t ms);

#ifdef __cplusplus
}
#endif

#endif
