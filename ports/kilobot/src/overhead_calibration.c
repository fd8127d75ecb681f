/* Calibrating, a hold of the overhead control: KiloGUI's calibration panel
 * moves the robot with the duties being tuned (in kilobot_calib, which
 * nothing of the app reads while held), and SAVE keeps them. The IR
 * interrupt only notes each request; the held kernel's clock handler acts
 * on them, because the motion's kick and the EEPROM writes take
 * milliseconds an interrupt must not hold the robot for. */
#include "openswarm/kernel.h"

#include "overhead_control_internal.h"

#define KICK_MS 15 /* at full duty: what a vibration motor needs to start */

static uint16_t uid; /* being calibrated */
static kilobot_motors motion;
static bool motion_due, save_due, kicking;
static uint16_t kick_start_ms;

/* The time, not a count of clock events: after a frame the IR driver
 * catches up the ticks it held back, several events at once. */
static uint16_t now_ms(void) { return (uint16_t)Sys_Get_SystemTime(); }

static void start_motion(void) {
    motion_due = false;
    kicking = true;
    kick_start_ms = now_ms();
    kilobot_motors_apply(motion.left ? 255 : 0, motion.right ? 255 : 0);
}

/* Every millisecond while calibrating. An interrupt that changes the
 * motion meanwhile leaves it due again: it starts over at the next tick. */
static bool on_clock(sys_pid pid, sys_event_id event, const sys_event_data *data) {
    (void)pid;
    (void)event;
    (void)data;
    if (save_due) {
        kilobot_calibration_save(uid);
        kilobot_restart(OVERHEAD_HOLD_MARK | KILOBOT_MESSAGE_WAKEUP); /* waits for RUN */
    }
    if (motion_due) {
        start_motion();
    } else if (kicking && (uint16_t)(now_ms() - kick_start_ms) >= KICK_MS) {
        kicking = false;
        kilobot_motors_apply(motion.left, motion.right);
    }
    return true;
}

/* The panel repeats its request while the user watches: only a change
 * starts the motion (and its kick) again. */
static void move(uint8_t left, uint8_t right) {
    if (left == motion.left && right == motion.right) return;
    motion.left = left;
    motion.right = right;
    motion_due = true;
}

static void take_calib(const uint8_t *d) {
    switch (d[KILOBOT_CALIB_AT_MODE]) {
    case KILOBOT_CALIB_SAVE:
        save_due = true;
        break;
    case KILOBOT_CALIB_UID:
        uid = (uint16_t)(d[KILOBOT_CALIB_AT_UID] | d[KILOBOT_CALIB_AT_UID + 1] << 8);
        move(0, 0);
        break;
    case KILOBOT_CALIB_TURN_LEFT:
        kilobot_calib.turn_left = d[KILOBOT_CALIB_AT_TURN_LEFT];
        move(kilobot_calib.turn_left, 0);
        break;
    case KILOBOT_CALIB_TURN_RIGHT:
        kilobot_calib.turn_right = d[KILOBOT_CALIB_AT_TURN_RIGHT];
        move(0, kilobot_calib.turn_right);
        break;
    case KILOBOT_CALIB_STRAIGHT:
        kilobot_calib.straight_left = d[KILOBOT_CALIB_AT_STRAIGHT_LEFT];
        kilobot_calib.straight_right = d[KILOBOT_CALIB_AT_STRAIGHT_RIGHT];
        move(kilobot_calib.straight_left, kilobot_calib.straight_right);
        break;
    default:
        break; /* a mode KiloGUI does not send */
    }
}

/* READUID: KiloGUI reads a uid bit by bit, watching which robots turn
 * left. */
static void show_uid_bit(uint8_t bit) {
    move(bit < 16 && (uid >> bit) & 1u ? kilobot_calib.turn_left : 0, 0);
}

void overhead_calibration_take(const uint8_t *frame) {
    uint8_t type = frame[OVERHEAD_TYPE_BYTE];
    if (type == KILOBOT_MESSAGE_CALIB) take_calib(frame);
    if (type == KILOBOT_MESSAGE_READUID) show_uid_bit(frame[0]);
}

void overhead_calibration_start(const uint8_t *frame) {
    uid = kilobot_uid();
    Sys_Subscribe_to_Event(SYS_EVENT_1MS_TIMER, SYS_PID_SYSTEM, on_clock, NULL);
    overhead_calibration_take(frame);
}
