/* An e-puck controller for the world link's test (epuck_link_test.py),
 * written against the e-puck's devices only, as any app for the robot:
 * what the camera sees sets the wheels (the clustering controller's
 * speeds, steps/s), and a thread blinks the RGB LEDs every 500 ms. It
 * says its id (robot_id: in the world, its index) on its console. */
#include <stdio.h>

#include "openswarm/kernel.h"
#include "openswarm/robot.h"

static bool steer(sys_pid pid, sys_event_id event, const sys_event_data *data) {
    (void)pid;
    (void)event;
    static const epuck_wheel_speeds by_seen[] = {
        [EPUCK_SEEN_NOTHING] = {550, 990},
        [EPUCK_SEEN_ROBOT] = {890, 530},
        [EPUCK_SEEN_OBJECT] = {980, 500},
    };
    uint8_t seen = *(const uint8_t *)data->value;
    if (seen <= EPUCK_SEEN_OBJECT) Sys_Send_Event(EPUCK_EVENT_WHEELS, &by_seen[seen], sizeof by_seen[0]);
    return true; /* stay subscribed */
}

static void blinker(void) {
    uint8_t colour = ROBOT_RGB(0, 0, 0);
    for (;;) {
        colour = colour != 0 ? ROBOT_RGB(0, 0, 0) : ROBOT_RGB(0, 3, 0);
        Sys_Send_Event(ROBOT_EVENT_LED, &colour, 1);
        Sys_Sleep(500);
    }
}

int main(void) {
    Sys_Init_Kernel();
    robot_devices_init();
    robot_console_init();
    printf("e-puck %u here\n", (unsigned)robot_id());
    Sys_Subscribe_to_Event(EPUCK_EVENT_CAMERA, SYS_PID_SYSTEM, steer, NULL);
    Sys_Start_Process(blinker);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
