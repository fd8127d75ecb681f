/* Fault reporting and the resource counters. */
#include "kernel_internal.h"

#include <string.h>

sys_stats os_stats;

void os_stats_reset(void) { memset(&os_stats, 0, sizeof os_stats); }

/* Counters stop at their top: one that wrapped could read 0 after 65536
 * losses. Tested after the increment (a wrap to 0 is not stored): on the
 * AVR that is 8 bytes shorter than comparing with UINT16_MAX first, which
 * kilolib's programs need (docs/benchmarks.md). */
OS_COLD void os_count(uint16_t *counter) {
    uint16_t next = (uint16_t)(*counter + 1u);
    if (next != 0) *counter = next;
}

void Sys_Get_Stats(sys_stats *stats) {
    port_irq_state_t s = port_irq_save();
    *stats = os_stats;
    port_irq_restore(s);
}

void Sys_Set_FaultHook(sys_fault_hook hook) {
    port_irq_state_t s = port_irq_save();
    os.fault_hook = hook;
    port_irq_restore(s);
}

/* Interrupts are masked here. */
void os_fault(sys_fault fault, sys_pid pid) {
    port_report_fault((uint8_t)fault, pid);
    if (os.fault_hook != NULL) os.fault_hook(fault, pid);
    sys_fault_info info = {(uint8_t)fault, pid};
    os_event_post(SYS_EVENT_FAULT, &info, (uint8_t)sizeof info); /* if registered */
}
