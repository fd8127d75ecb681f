/* Hardware-independent motion commands through the motors' default
 * post-processor (this robot's EEPROM calibration, set by the simulator's
 * --calibration), then the spin-up safety post-processor. Checked by trace. */
#include "openswarm/kernel.h"
#include "openswarm/kilobot.h"
#include "openswarm/kilobot_sim.h"

static void move(kilobot_motion m) {
    uint8_t byte = (uint8_t)m;
    Sys_Send_Event(KILOBOT_EVENT_MOTORS, &byte, 1);
}

static const kilobot_spinup_limit limit = {50, 100};

static void script(void *arg) {
    (void)arg;
    move(KILOBOT_FORWARD);
    Sys_Sleep(100);
    move(KILOBOT_TURN_LEFT);
    Sys_Sleep(100);
    move(KILOBOT_TURN_RIGHT);
    Sys_Sleep(100);
    move(KILOBOT_STOP);
    Sys_Sleep(100);
    Sys_Set_Processor(&kilobot_motor_pair, kilobot_spinup_limited, (void *)&limit);
    kilobot_motors full = {255, 255};
    Sys_Send_Event(KILOBOT_EVENT_MOTORS, &full, sizeof full); /* dropped to 100 after 50 ms */
    Sys_Sleep(100);
    move(KILOBOT_STOP);
    Sys_Sleep(10);
    sim_exit(0);
}

int main(void) {
    Sys_Init_Kernel();
    if (kilobot_devices_init() != SYS_OK) sim_exit(2);
    Sys_Start_Process_Ex(script, NULL, 96, 0, NULL);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
