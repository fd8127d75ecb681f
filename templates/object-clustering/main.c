/* {{name}}: e-pucks push objects together with nothing but their camera
 * (the OpenSwarm paper's case study, after Gauci et al. 2014, "Clustering
 * objects with robots that do not compute").
 *
 * The camera device's frames go through its classifier processor - the
 * paper's virtual sensor - which turns each into an event saying what is
 * straight ahead: another robot (green), an object (red) or nothing (the
 * white walls). A handler maps that to a pair of wheel speeds, and the
 * wheels' safety processor keeps the steppers from jumping between them.
 * That is the whole controller: no memory, no arithmetic. */
#include "openswarm/kernel.h"
#include "openswarm/robot.h"
#include "openswarm_app.h"

/* Gauci et al.'s speeds, as fractions of the top speed (left, right):
 * robot ahead (0.89, 0.53), object ahead (0.98, 0.50), nothing (0.55,
 * 0.99); here in steps/s of EPUCK_MAX_STEPS_PER_S (1000, about 129 mm/s). */
static const epuck_wheel_speeds speeds_for[] = {
    [EPUCK_SEEN_NOTHING] = {550, 990},
    [EPUCK_SEEN_ROBOT] = {890, 530},
    [EPUCK_SEEN_OBJECT] = {980, 500},
};

static bool steer(sys_pid pid, sys_event_id event, const sys_event_data *data) {
    (void)pid;
    (void)event;
    uint8_t seen = *(const uint8_t *)data->value;
    if (seen <= EPUCK_SEEN_OBJECT)
        Sys_Send_Event(EPUCK_EVENT_WHEELS, &speeds_for[seen], sizeof speeds_for[0]);
    return true; /* stay subscribed */
}

int main(void) {
    Sys_Init_Kernel();
    robot_devices_init();
    openswarm_app_start();
    Sys_Subscribe_to_Event(EPUCK_EVENT_CAMERA, SYS_PID_SYSTEM, steer, NULL);
    Sys_Start_Kernel();
    Sys_Run_SystemThread(); /* main becomes the system thread */
    return 0;
}
