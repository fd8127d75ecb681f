/* {{name}}: start here. The kernel and the robot's devices are set up; put
 * your work in app_thread, or subscribe handlers to events. */
#include "openswarm/kernel.h"
#include "openswarm/robot.h"

static void app_thread(void) {
    for (;;) {
        Sys_Sleep(1000);
    }
}

int main(void) {
    Sys_Init_Kernel();
    robot_devices_init();
    Sys_Start_Process(app_thread);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
