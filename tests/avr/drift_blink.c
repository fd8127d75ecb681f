/* A blinker timed by the kernel's clock alone: the LED on for a
 * Sys_Sleep(1000), off for another. Run beside an undrifted twin with
 * --faults drift:ROBOT=PCT, its LED's edges in world time show how fast its
 * clock runs (avr.fault_clock_drift). */
#include "openswarm/kernel.h"
#include "openswarm/robot.h"

static void blinker(void) {
    for (;;) {
        uint8_t colour = ROBOT_RGB(0, 3, 0);
        Sys_Send_Event(ROBOT_EVENT_LED, &colour, 1);
        Sys_Sleep(1000);
        colour = ROBOT_RGB(0, 0, 0);
        Sys_Send_Event(ROBOT_EVENT_LED, &colour, 1);
        Sys_Sleep(1000);
    }
}

int main(void) {
    Sys_Init_Kernel();
    robot_devices_init();
    Sys_Start_Process(blinker);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
