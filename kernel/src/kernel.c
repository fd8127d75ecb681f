/* Kernel start-up and the system thread. */
#include "kernel_internal.h"

#include <string.h>

os_kernel os;

void Sys_Init_Kernel(void) {
    port_irq_disable();
    memset(&os, 0, sizeof os);
    os_stats_reset();
    /* Free slots; their pids get the slot when a thread starts in one. */
    for (unsigned i = 1; i < OS_CFG_MAX_THREADS; i++) os.threads[i].state = OS_SLOT_FREE;
    os.current = OS_SYSTEM;
    OS_SYSTEM->state = SYS_PROCESS_RUNNING;
    OS_SYSTEM->pid = SYS_PID_SYSTEM;
    os_scheduler_reset();
    os_event_table_reset();
    os_event_queue_reset();
    os_hal_reset();
    os_stack_pool_reset();
    port_init();
#if OS_CFG_CLOCK_EVENT
    Sys_Register_Event_Sized(SYS_EVENT_1MS_TIMER, (uint8_t)sizeof(uint32_t));
#endif
    Sys_Register_Event_Sized(SYS_EVENT_FAULT, (uint8_t)sizeof(sys_fault_info));
}

void Sys_Start_Kernel(void) {
    port_tick_start();
    port_irq_enable();
}

void Sys_Run_SystemThread(void) {
    port_irq_disable();
    while ((os.system_work & OS_WORK_STOP) == 0) {
        if (os_reap_pending()) {
            os_reap_zombies();
        } else if (!os_event_queue_empty()) {
            os_dispatch_all();
        } else {
            /* It gives the CPU away as a thread that stops running does:
             * to the thread its work preempted, or the ready list. */
            OS_SYSTEM->state = SYS_PROCESS_READY;
            if (!os_decide()) os_idle(); /* nobody else can run */
        }
    }
    os.system_work &= (uint8_t)~OS_WORK_STOP;
    port_irq_enable();
}

void Sys_Stop_Kernel(void) {
    port_irq_state_t s = port_irq_save();
    os.system_work |= OS_WORK_STOP;
    os.reconsider = true;
    os_schedule();
    port_irq_restore(s);
}
