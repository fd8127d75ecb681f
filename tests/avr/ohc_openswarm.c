/* An app on the OpenSwarm API under the overhead controller: robot_devices_init()
 * answers its system messages (avr.ohc_*). The app says when it starts,
 * with the identity it starts with (robot_id() and kilobot_calib, which
 * calibration changes), and what IR frames reach it, and blinks green
 * every 100 ms. Built also with KILOBOT_OVERHEAD_CONTROL 0 (ohc_opt_out):
 * the system messages then reach the app as frames; and 2, the messages
 * as events it has no handler for (ohc_events_unhandled). */
#include "openswarm/kernel.h"
#include "openswarm/kilobot_sim.h"
#include "openswarm/robot.h"

static bool heard(sys_pid pid, sys_event_id event, const sys_event_data *data) {
    (void)pid;
    (void)event;
    const kilobot_ir_rx *rx = (const kilobot_ir_rx *)data->value;
    sim_puts_P(PSTR("app heard a frame of type "));
    sim_put_uint(rx->frame[9]);
    sim_putc('\n');
    return true;
}

static void say_identity(void) {
    const uint8_t duties[] = {kilobot_calib.turn_left, kilobot_calib.turn_right,
                              kilobot_calib.straight_left, kilobot_calib.straight_right};
    sim_puts_P(PSTR("app starts: uid "));
    sim_put_uint(robot_id());
    sim_puts_P(PSTR(", calibration"));
    for (uint8_t i = 0; i < sizeof duties; i++) {
        sim_putc(' ');
        sim_put_uint(duties[i]);
    }
    sim_putc('\n');
}

static void blinker(void) {
    for (;;) {
        uint8_t colour = ROBOT_RGB(0, 3, 0);
        Sys_Send_Event(ROBOT_EVENT_LED, &colour, 1);
        Sys_Sleep(100);
        colour = ROBOT_RGB(0, 0, 0);
        Sys_Send_Event(ROBOT_EVENT_LED, &colour, 1);
        Sys_Sleep(100);
    }
}

int main(void) {
    Sys_Init_Kernel();
    robot_devices_init();
    say_identity();
    Sys_Subscribe_to_Event(KILOBOT_EVENT_IR_RX, SYS_PID_SYSTEM, heard, NULL);
    Sys_Start_Process(blinker);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
