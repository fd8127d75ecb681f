/* The motors' processors (calibrated motion commands, a spin-up limit) and
 * the calibration they use, as the EEPROM keeps it. */
#include "openswarm/kilobot.h"

#include <avr/eeprom.h>

#include "devices_internal.h"

kilobot_calibration kilobot_calib;

void kilobot_calibration_load(void) {
    kilobot_calib.turn_left = eeprom_read_byte((const uint8_t *)KILOBOT_EEPROM_TURN_LEFT);
    kilobot_calib.turn_right = eeprom_read_byte((const uint8_t *)KILOBOT_EEPROM_TURN_RIGHT);
    kilobot_calib.straight_left = eeprom_read_byte((const uint8_t *)KILOBOT_EEPROM_STRAIGHT_LEFT);
    kilobot_calib.straight_right = eeprom_read_byte((const uint8_t *)KILOBOT_EEPROM_STRAIGHT_RIGHT);
}

/* Updates, not writes: an EEPROM cell wears out after about 100 000. */
void kilobot_calibration_save(uint16_t uid) {
    eeprom_update_word((uint16_t *)KILOBOT_EEPROM_UID, uid);
    eeprom_update_byte((uint8_t *)KILOBOT_EEPROM_TURN_LEFT, kilobot_calib.turn_left);
    eeprom_update_byte((uint8_t *)KILOBOT_EEPROM_TURN_RIGHT, kilobot_calib.turn_right);
    eeprom_update_byte((uint8_t *)KILOBOT_EEPROM_STRAIGHT_LEFT, kilobot_calib.straight_left);
    eeprom_update_byte((uint8_t *)KILOBOT_EEPROM_STRAIGHT_RIGHT, kilobot_calib.straight_right);
}

/* A motion byte becomes calibrated duties, two bytes pass as they are. */
static uint8_t to_duties(const void *in, uint8_t size, void *out, uint8_t capacity) {
    kilobot_motors *m = out;
    if (capacity < sizeof *m) return 0;
    if (size == sizeof *m) {
        *m = *(const kilobot_motors *)in;
        return sizeof *m;
    }
    if (size != 1) return 0; /* neither duties nor a motion: rejected */
    switch (*(const uint8_t *)in) {
    case KILOBOT_STOP: m->left = m->right = 0; break;
    case KILOBOT_FORWARD:
        m->left = kilobot_calib.straight_left;
        m->right = kilobot_calib.straight_right;
        break;
    case KILOBOT_TURN_LEFT:
        m->left = kilobot_calib.turn_left;
        m->right = 0;
        break;
    case KILOBOT_TURN_RIGHT:
        m->left = 0;
        m->right = kilobot_calib.turn_right;
        break;
    default: return 0;
    }
    return sizeof *m;
}

uint8_t kilobot_motor_commands(sys_device *dev, const void *in, uint8_t size, void *out,
                               uint8_t capacity) {
    (void)dev;
    kilobot_motors_unlimit(); /* no limit unless kilobot_spinup_limited runs */
    return to_duties(in, size, out, capacity);
}

uint8_t kilobot_spinup_limited(sys_device *dev, const void *in, uint8_t size, void *out,
                               uint8_t capacity) {
    uint8_t n = to_duties(in, size, out, capacity);
    const kilobot_spinup_limit *limit = dev->params;
    /* The processor decides; the motors' 1 ms tick enforces it in time. */
    if (n != 0 && limit != NULL) kilobot_motors_limit_full_power(limit->limit_ms, limit->fallback);
    return n;
}
