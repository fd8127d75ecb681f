/* A program on the system thread: code that runs on main()'s stack between
 * dispatches, as a classic single-loop firmware's main loop does (kilolib's
 * setup() and loop()). It needs no thread, so no stack of its own: the
 * handlers that preempt it run on top of it, on the same stack, as the
 * classic library's interrupt callbacks do. Its waits (Sys_Idle) are where
 * the system thread does its own work, runs the ready threads and idles. */
#include "kernel_internal.h"

/* The system thread's work - reaping, then the queued occurrences - until
 * none is left. Interrupts masked. */
static void system_work(void) {
    while (os_reap_pending() || !os_event_queue_empty()) {
        if (os_reap_pending())
            os_reap_zombies();
        else
            os_dispatch_all();
    }
}

/* os_schedule and the end of an interrupt, as the program runs: what was
 * sent is dispatched now, nested on its stack, as it would be for a thread.
 * The flag is down meanwhile, so the handlers' own sends and interrupts
 * join this dispatch instead of nesting a second one. */
void os_program_preempted(void) {
    if (!os.program_running || (!os_reap_pending() && os_event_queue_empty())) return;
    os.program_running = false;
    system_work();
    os.program_running = true;
}

void Sys_Run_SystemProgram(void (*program)(void)) {
    port_irq_disable();
    system_work(); /* what set-up sent, before the program sees anything */
    os.program_running = true;
    port_irq_enable();
    program();
    port_irq_disable();
    os.program_running = false;
    port_irq_enable();
    Sys_Run_SystemThread();
}

bool Sys_In_SystemProgram(void) {
    return os.program_running && os.isr_depth == 0 && os.current == OS_SYSTEM;
}

/* The program waits: the system thread's work first; if there was none,
 * the ready threads run (the program resumes when none is left) or the CPU
 * sleeps until an interrupt, at most max_ms. One turn: the caller asks
 * again until what it waits for has come. */
sys_status Sys_Idle(uint32_t max_ms) {
    if (!Sys_In_SystemProgram()) return SYS_E_CONTEXT;
    port_irq_disable();
    os.program_running = false;
    if (os_reap_pending() || !os_event_queue_empty()) {
        system_work();
    } else {
        OS_SYSTEM->state = SYS_PROCESS_READY;
        if (OS_CFG_MAX_THREADS == 1 || !os_decide()) os_idle_at_most(max_ms);
        OS_SYSTEM->state = SYS_PROCESS_RUNNING;
        system_work(); /* what the interrupt that woke it sent */
    }
    os.program_running = true;
    port_irq_enable();
    return SYS_OK;
}
