/* A handler that never returns is reported: a thread sends an event whose
 * handler spins for ever (on the system thread, between threads); the
 * kernel's tick says so once, when it has run OS_CFG_HANDLER_LIMIT_MS (1 s
 * by default), and the simulator fails the run (avr.handler_overrun). */
#include "openswarm/kernel.h"
#include "openswarm/kilobot_sim.h"

#define EV_STUCK SYS_EVENT_FIRST_FREE

static volatile uint8_t spinning;

static bool stuck(sys_pid pid, sys_event_id e, const sys_event_data *d) {
    (void)pid;
    (void)e;
    (void)d;
    sim_puts_P(PSTR("handler starts spinning\n"));
    for (spinning = 1;;) {
    }
    return true;
}

static void sender(void *arg) {
    (void)arg;
    Sys_Sleep(100);
    Sys_Send_Event(EV_STUCK, NULL, 0);
    sim_puts_P(PSTR("never: the handler runs before the send returns\n"));
}

int main(void) {
    Sys_Init_Kernel();
    Sys_Register_Event_Sized(EV_STUCK, 0);
    Sys_Subscribe_to_Event(EV_STUCK, SYS_PID_SYSTEM, stuck, NULL);
    Sys_Start_Process_Ex(sender, NULL, 96, 0, NULL);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
