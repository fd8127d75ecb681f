/* Blink with events, in C: the twin of blink_events.cpp, which must
 * compile to the same code size (the C++ SDK costs nothing). */
#include "openswarm/kernel.h"
#include "openswarm/kilobot.h"

#define EV_LEVEL SYS_EVENT_FIRST_FREE

static bool show_level(sys_pid pid, sys_event_id event, const sys_event_data *data) {
    (void)pid;
    (void)event;
    uint8_t level = *(const uint8_t *)data->value;
    uint8_t colour = KILOBOT_RGB(0, level, 0);
    Sys_Send_Event(KILOBOT_EVENT_LED, &colour, 1);
    return true;
}

static void pulse(void) {
    for (uint8_t level = 0;; level = (uint8_t)((level + 1) & 3)) {
        Sys_Start_CriticalSection();
        Sys_Send_Event(EV_LEVEL, &level, sizeof level);
        Sys_End_CriticalSection();
        Sys_Sleep(100);
    }
}

int main(void) {
    Sys_Init_Kernel();
    kilobot_devices_init();
    Sys_Register_Event_Sized(EV_LEVEL, sizeof(uint8_t));
    Sys_Subscribe_to_Event(EV_LEVEL, SYS_PID_SYSTEM, show_level, NULL);
    Sys_Start_Process(pulse);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
