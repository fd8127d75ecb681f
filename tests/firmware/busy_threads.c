#include "busy_threads.h"

#include "openswarm/kernel.h"

static volatile uint32_t spins[2];

static void spinner(void *arg) {
    volatile uint32_t *count = arg;
    for (;;) (*count)++;
}

busy_threads_result busy_threads_run(void) {
    Sys_Start_Process_Ex(spinner, (void *)&spins[0], 0, 0, NULL);
    Sys_Start_Process_Ex(spinner, (void *)&spins[1], 0, 0, NULL);
    uint32_t switches = Sys_Get_SwitchCount();
    Sys_Sleep(200);
    busy_threads_result result = {Sys_Get_SystemTime(), Sys_Get_SwitchCount() - switches,
                                  spins[0] != 0 && spins[1] != 0};
    return result;
}
