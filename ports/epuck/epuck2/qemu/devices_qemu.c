/* The robot's devices as the QEMU board has them: QEMU models none of the
 * e-puck2's (no GPIO, no ESP32), so the status light is a record on the
 * console (board_record.h) that `openswarm run` shows. */
#include "board_record.h"
#include "openswarm/hal.h"
#include "openswarm/robot.h"

static void status_light_write(sys_device *dev, const void *raw, uint8_t size) {
    (void)dev;
    if (size < 1) return;
    uint8_t rgb = *(const uint8_t *)raw;
    uint8_t channels[3] = {(uint8_t)(rgb & 3u), (uint8_t)((rgb >> 2) & 3u), (uint8_t)((rgb >> 4) & 3u)};
    board_record("led", channels, 3);
}

static sys_device status_light = {"led", SYS_DEVICE_OUTPUT, ROBOT_EVENT_LED, 0, NULL, NULL,
                                  status_light_write, NULL, 0};

sys_status robot_devices_init(void) { return Sys_Register_Device(&status_light); }
