/* Registering the Kilobot's devices with the HAL. */
#include <avr/eeprom.h>

#include "openswarm/kilobot.h"

#include "devices_internal.h"

sys_status kilobot_devices_init(void) {
    kilobot_calibration_load();
    sys_status st = Sys_Register_Device(&kilobot_led);
    if (st == SYS_OK) st = Sys_Register_Device(&kilobot_motor_pair);
    if (st == SYS_OK) st = Sys_Register_Device(&kilobot_ir);
    if (st == SYS_OK) kilobot_ir_start();
    return st;
}

uint16_t kilobot_uid(void) { return eeprom_read_word((const uint16_t *)KILOBOT_EEPROM_UID); }
