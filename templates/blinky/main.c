/* {{name}}: a thread blinks the LED through the HAL's LED device; an event
 * handler, run by the kernel between threads, counts the blinks.
 * openswarm.json declares the thread and the event: `openswarm build`
 * turns it into openswarm_app.h (EV_BLINK) and openswarm_app_start(). */
#include "openswarm/kernel.h"
#include "openswarm/robot.h"
#include "openswarm_app.h"

static uint16_t blinks;

static bool count_blink(sys_pid pid, sys_event_id event, const sys_event_data *data) {
    (void)pid;
    (void)event;
    (void)data;
    blinks++;
    return true; /* stay subscribed */
}

void blinker(void) {
    for (;;) {
        uint8_t colour = ROBOT_RGB(0, 3, 0);
        Sys_Send_Event(ROBOT_EVENT_LED, &colour, 1);
        Sys_Send_Event(EV_BLINK, NULL, 0);
        Sys_Sleep(250);
        colour = ROBOT_RGB(0, 0, 0);
        Sys_Send_Event(ROBOT_EVENT_LED, &colour, 1);
        Sys_Sleep(250);
    }
}

int main(void) {
    Sys_Init_Kernel();
    robot_devices_init();
    openswarm_app_start();
    Sys_Subscribe_to_Event(EV_BLINK, SYS_PID_SYSTEM, count_blink, NULL);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
