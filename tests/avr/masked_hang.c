/* A thread that masks interrupts and then spins for ever: no tick runs
 * again, so the kernel's own watches cannot see it; the simulator reports
 * it once interrupts have been masked past its limit (1 s by default) and
 * fails the run with exit 7 (avr.masked_hang). */
#include <avr/interrupt.h>

#include "openswarm/kernel.h"
#include "openswarm/kilobot_sim.h"

static volatile uint8_t spinning;

static void masker(void *arg) {
    (void)arg;
    Sys_Sleep(100);
    sim_puts_P(PSTR("masking interrupts for ever\n"));
    cli();
    for (spinning = 1;;) {
    }
}

int main(void) {
    Sys_Init_Kernel();
    Sys_Start_Process_Ex(masker, NULL, 96, 0, NULL);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
