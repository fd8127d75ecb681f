/* A minimal application: one thread that waits for the clock. */
#include "openswarm/kernel.h"

static void worker(void) {
    for (;;) Sys_Sleep(100);
}

int main(void) {
    Sys_Init_Kernel();
    Sys_Start_Process(worker);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
