/* Registering the Kilobot's devices with the HAL. */
#include <avr/eeprom.h>

#include "openswarm/kilobot.h"

#include "devices_internal.h"

/* Each device's events at its values' sizes, not the HAL's largest (17
 * bytes, an IR reception): the 38 bytes of kept data this saves pay for an
 * event queue that holds the frames a crowd sends back to back
 * (port_config.h). A larger value is refused when it is sent
 * (SYS_E_TOO_BIG), as the device would refuse it anyway. */
static sys_status register_sized(sys_event_id event, uint8_t size) {
    sys_status st = Sys_Register_Event_Sized(event, size);
    return st == SYS_E_EXISTS ? SYS_OK : st; /* the app's own registration stands */
}

/* Calls, not a table: a table of constants would take RAM on the AVR. */
static sys_status register_value_sizes(void) {
    sys_status st = register_sized(KILOBOT_EVENT_LED, 1);
    if (st == SYS_OK) st = register_sized(KILOBOT_EVENT_MOTORS, sizeof(kilobot_motors));
    if (st == SYS_OK) st = register_sized(KILOBOT_EVENT_IR_RX, sizeof(kilobot_ir_rx));
    if (st == SYS_OK) st = register_sized(KILOBOT_EVENT_IR_TX, KILOBOT_IR_FRAME_BYTES - 2u); /* the Tx processor adds the CRC */
    return st;
}

sys_status kilobot_devices_init(void) {
    kilobot_calibration_load();
    sys_status st = register_value_sizes();
    if (st == SYS_OK) st = Sys_Register_Device(&kilobot_led);
    if (st == SYS_OK) st = Sys_Register_Device(&kilobot_motor_pair);
    if (st == SYS_OK) st = Sys_Register_Device(&kilobot_ir);
    if (st == SYS_OK) kilobot_ir_start();
    return st;
}

uint16_t kilobot_uid(void) { return eeprom_read_word((const uint16_t *)KILOBOT_EEPROM_UID); }
