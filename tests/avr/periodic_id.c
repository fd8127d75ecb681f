/* The robot's own id without EEPROM code (robot_id()), and a periodic
 * loop that keeps its period exactly whatever its work takes
 * (Sys_Sleep_Until): a Sys_Sleep(1000) loop with 13 ms of work drifted to
 * 1.013, 2.026, 3.039 s; and printf without kilolib's headers
 * (robot_console_init) (avr.periodic_id). */
#include <stdio.h>

#include "openswarm/kernel.h"
#include "openswarm/kilobot_sim.h"
#include "openswarm/robot.h"

static void periodic(void) {
    uint32_t wake = Sys_Get_SystemTime();
    for (int k = 0; k < 3; k++) {
        Sys_Sleep_Until(&wake, 1000);
        sim_puts_P(PSTR("woke at "));
        sim_put_uint(Sys_Get_SystemTime());
        sim_puts_P(PSTR(" ms\n"));
        Sys_Sleep(13); /* the loop's work */
    }
    sim_exit(0);
}

int main(void) {
    Sys_Init_Kernel();
    robot_devices_init();
    robot_console_init();
    printf("printf says %d\n", 42);
    sim_puts_P(PSTR("robot id "));
    sim_put_uint(robot_id());
    sim_putc('\n');
    Sys_Start_Process(periodic);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
