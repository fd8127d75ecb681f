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

/* Block the calling thread until *wake_ms + period_ms, and set *wake_ms
 * to that time: a loop calling it runs once every period_ms exactly,
 * whatever its own work takes (a Sys_Sleep loop drifts by that much each
 * time). Start with *wake_ms = Sys_Get_SystemTime(). When that time has
 * passed already (the work took longer than a period), it returns at once
 * and the loop catches up. SYS_E_INVALID for a NULL wake_ms; otherwise as
 * Sys_Sleep (SYS_E_CONTEXT from a handler, an interrupt or a critical
 * section). */
sys_status Sys_Sleep_Until(uint32_t *wake_ms, uint32_t period_ms);

#ifdef __cplusplus
}
#endif

#endif
