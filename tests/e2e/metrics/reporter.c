/* A test program for `openswarm metrics`: each robot reports its uid once
 * and how often it has blinked, as console lines "metric NAME VALUE". */
#include <stdio.h>

#include "openswarm/kernel.h"
#include "openswarm/robot.h"
#include "openswarm_app.h"

void blinker(void) {
    unsigned blinks = 0;
    printf("metric uid %u\n", robot_id());
    for (;;) {
        uint8_t colour = ROBOT_RGB(0, 3, 0);
        Sys_Send_Event(ROBOT_EVENT_LED, &colour, 1);
        printf("metric blinks %u\n", ++blinks);
        Sys_Sleep(250);
        colour = ROBOT_RGB(0, 0, 0);
        Sys_Send_Event(ROBOT_EVENT_LED, &colour, 1);
        Sys_Sleep(250);
    }
}

int main(void) {
    Sys_Init_Kernel();
    robot_devices_init();
    robot_console_init();
    openswarm_app_start();
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
