/* A minimal application: USER_THREADS threads (1 unless the build says
 * otherwise) that wait for the clock. */
#include "openswarm/kernel.h"

#ifndef USER_THREADS
#define USER_THREADS 1
#endif

static void worker(void) {
    for (;;) Sys_Sleep(100);
}

int main(void) {
    Sys_Init_Kernel();
    for (unsigned i = 0; i < USER_THREADS; i++) Sys_Start_Process(worker);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
