/* An app on the OpenSwarm API that takes the overhead controller's
 * messages as events (KILOBOT_OVERHEAD_CONTROL_EVENTS; avr.ohc_events_*):
 * it drives forward and blinks green; KiloGUI's Pause (WAKEUP) stops its
 * motors and blinking and RUN starts them again, without a restart;
 * RESET is vetoed; every other message goes to the port's action. It says
 * when it starts and what it got, and when. */
#define KILOBOT_OVERHEAD_CONTROL KILOBOT_OVERHEAD_CONTROL_EVENTS
#include "openswarm/kernel.h"
#include "openswarm/kilobot_sim.h"
#include "openswarm/robot.h"

static volatile bool paused;

static void drive(uint8_t duty) {
    kilobot_motors motors = {duty, duty};
    Sys_Send_Event(KILOBOT_EVENT_MOTORS, &motors, sizeof motors);
}

static void say(const char *what, uint8_t type) {
    sim_puts_P(what);
    sim_put_uint(type);
    sim_puts_P(PSTR(" at "));
    sim_put_uint(Sys_Get_SystemTime());
    sim_puts_P(PSTR(" ms\n"));
}

static bool on_overhead_controller(sys_pid pid, sys_event_id event, const sys_event_data *data) {
    (void)pid;
    (void)event;
    const kilobot_ohc_message *m = (const kilobot_ohc_message *)data->value;
    say(PSTR("app got system message "), m->type);
    if (m->type == KILOBOT_MESSAGE_WAKEUP) { /* KiloGUI's Pause */
        paused = true;
        drive(0);
    } else if (m->type == KILOBOT_MESSAGE_RUN) {
        paused = false;
        drive(100);
    } else if (m->type == KILOBOT_MESSAGE_RESET) {
        say(PSTR("app vetoed "), m->type);
    } else {
        kilobot_overhead_control_act(m);
    }
    return true;
}

static bool heard(sys_pid pid, sys_event_id event, const sys_event_data *data) {
    (void)pid;
    (void)event;
    say(PSTR("app heard a frame of type "), ((const kilobot_ir_rx *)data->value)->frame[9]);
    return true;
}

static void blinker(void) {
    for (uint8_t on = 1;; on ^= 1) {
        uint8_t colour = on && !paused ? ROBOT_RGB(0, 3, 0) : ROBOT_RGB(0, 0, 0);
        Sys_Send_Event(ROBOT_EVENT_LED, &colour, 1);
        Sys_Sleep(100);
    }
}

int main(void) {
    Sys_Init_Kernel();
    if (robot_devices_init() != SYS_OK) sim_puts_P(PSTR("robot_devices_init failed\n"));
    sim_puts_P(PSTR("app starts\n"));
    Sys_Subscribe_to_Event(KILOBOT_EVENT_OHC, SYS_PID_SYSTEM, on_overhead_controller, NULL);
    Sys_Subscribe_to_Event(KILOBOT_EVENT_IR_RX, SYS_PID_SYSTEM, heard, NULL);
    drive(100);
    Sys_Start_Process(blinker);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
