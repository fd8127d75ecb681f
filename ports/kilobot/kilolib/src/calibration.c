/* Calibration from the overhead controller (KiloGUI's calibration panel):
 * the program stops, the robot moves with the duties the user is tuning,
 * and SAVE keeps them (and the uid) in the EEPROM. */
#include <avr/eeprom.h>

#include "kilolib_internal.h"
#include "openswarm/kilobot.h"

static uint8_t moving_left, moving_right; /* duties of the calibration motion */

static void calibration_motion(void) {
    set_motors(moving_left ? 255 : 0, moving_right ? 255 : 0); /* vibration motors need a kick */
    delay(15);
    set_motors(moving_left, moving_right);
}

/* The panel repeats a mode while the user watches: only a change restarts
 * the motion (and its spin-up). */
static void move(uint8_t left, uint8_t right) {
    if (kilolib_activity() == CALIB && left == moving_left && right == moving_right) return;
    moving_left = left;
    moving_right = right;
    kilolib_activity_start(CALIB, calibration_motion);
}

/* Only values being calibrated are saved (a stray SAVE changes nothing);
 * then the robot waits for RUN, as after a reset. */
static void save(void) {
    if (kilolib_activity() != CALIB) return;
    eeprom_update_word((uint16_t *)KILOBOT_EEPROM_UID, kilo_uid);
    eeprom_update_byte((uint8_t *)KILOBOT_EEPROM_TURN_LEFT, kilo_turn_left);
    eeprom_update_byte((uint8_t *)KILOBOT_EEPROM_TURN_RIGHT, kilo_turn_right);
    eeprom_update_byte((uint8_t *)KILOBOT_EEPROM_STRAIGHT_LEFT, kilo_straight_left);
    eeprom_update_byte((uint8_t *)KILOBOT_EEPROM_STRAIGHT_RIGHT, kilo_straight_right);
    kilolib_identity_load(); /* the motors' motion commands use them too */
    kilolib_activity_start(WAKEUP, kilolib_status_lights);
}

/* READUID: KiloGUI reads a uid bit by bit (data[0] is the bit), watching
 * which robots turn left. */
static void show_uid_bit(uint8_t bit) {
    move(bit < 16 && (kilo_uid >> bit) & 1u ? kilo_turn_left : 0, 0);
}

void kilolib_calibration_message(const message_t *msg) {
    const uint8_t *d = msg->data;
    if (msg->type == READUID) {
        show_uid_bit(d[0]);
        return;
    }
    switch (d[KILOBOT_CALIB_AT_MODE]) {
    case KILOBOT_CALIB_SAVE:
        save();
        break;
    case KILOBOT_CALIB_UID:
        kilo_uid = (uint16_t)(d[KILOBOT_CALIB_AT_UID] | d[KILOBOT_CALIB_AT_UID + 1] << 8);
        move(0, 0);
        break;
    case KILOBOT_CALIB_TURN_LEFT:
        kilo_turn_left = d[KILOBOT_CALIB_AT_TURN_LEFT];
        move(kilo_turn_left, 0);
        break;
    case KILOBOT_CALIB_TURN_RIGHT:
        kilo_turn_right = d[KILOBOT_CALIB_AT_TURN_RIGHT];
        move(0, kilo_turn_right);
        break;
    case KILOBOT_CALIB_STRAIGHT:
        kilo_straight_left = d[KILOBOT_CALIB_AT_STRAIGHT_LEFT];
        kilo_straight_right = d[KILOBOT_CALIB_AT_STRAIGHT_RIGHT];
        move(kilo_straight_left, kilo_straight_right);
        break;
    default:
        break; /* a mode this library does not know */
    }
}
