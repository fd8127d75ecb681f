/* The Kilobot's LED and motors driven through the HAL, checked from the
 * outside: openswarm-sim --trace-csv records what the pins and the PWM
 * registers did, and expect_trace.py compares it with devices_suite.expected.
 * A thread paces the changes 100 ms apart; an interrupt-free run. */
#include "openswarm/kernel.h"
#include "openswarm/kilobot.h"
#include "openswarm/kilobot_sim.h"

static void led(uint8_t rgb) { Sys_Send_Event(KILOBOT_EVENT_LED, &rgb, 1); }

static void motors(uint8_t left, uint8_t right) {
    kilobot_motors m = {left, right};
    Sys_Send_Event(KILOBOT_EVENT_MOTORS, &m, sizeof m);
}

/* A safety post-processor: full power at most on one motor at a time. */
static uint8_t one_motor_at_full_power(sys_device *dev, const void *in, uint8_t size, void *out,
                                       uint8_t cap) {
    (void)dev;
    (void)cap;
    kilobot_motors m = *(const kilobot_motors *)in;
    if (m.left == 255 && m.right == 255) m.right = 128;
    *(kilobot_motors *)out = m;
    return size;
}

static void script(void *arg) {
    (void)arg;
    led(KILOBOT_RGB(3, 0, 0));
    Sys_Sleep(100);
    led(KILOBOT_RGB(0, 3, 0));
    Sys_Sleep(100);
    led(KILOBOT_RGB(1, 2, 3));
    Sys_Sleep(100);
    led(KILOBOT_RGB(0, 0, 0));
    motors(255, 0);
    Sys_Sleep(100);
    motors(0, 200);
    Sys_Sleep(100);
    Sys_Set_Processor(&kilobot_motor_pair, one_motor_at_full_power, NULL);
    motors(255, 255);
    Sys_Sleep(100);
    motors(0, 0);
    Sys_Sleep(10);
    sim_exit(Sys_IsEventRegistered(KILOBOT_EVENT_LED) ? 0 : 1);
}

int main(void) {
    Sys_Init_Kernel();
    if (kilobot_devices_init() != SYS_OK) sim_exit(2);
    Sys_Start_Process_Ex(script, NULL, 96, 0, NULL);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
