/* The overhead controller's system messages for apps on the OpenSwarm API
 * (kilobot.h): what KiloGUI's buttons do to a robot, whatever the app.
 *
 * A hold (SLEEP, WAKEUP, CHARGE, VOLTAGE, and calibrating, which CALIB and
 * READUID ask for) is a restart with a mark: the app's main() runs up to
 * robot_devices_init(), which sees the mark and runs the kernel with the
 * devices alone, so nothing of the app runs and everything of it starts
 * afresh at RUN, as a kilolib program's setup() does. The actions are
 * taken where the frame is checked, in the IR interrupt: each is a jump
 * that needs nothing of the kernel, or, while calibrating, a request noted
 * for the held kernel (overhead_calibration.c). */
#include <string.h>

#include "openswarm/kernel.h"
#include "openswarm/kilobot.h"

#include "overhead_control_internal.h"

#define HOLD_LIGHT KILOBOT_RGB(0, 0, 1) /* dim blue: held, awake */
/* Calibrating, whether CALIB or READUID asked for it. */
#define CALIBRATING KILOBOT_MESSAGE_CALIB

static bool active;
static uint8_t held; /* the hold's type, 0 while the app runs */
/* The request that began calibrating, for the run the restart begins. */
static uint8_t calibration_request[KILOBOT_IR_FRAME_BYTES] __attribute__((section(".noinit")));

static bool is_hold(uint8_t type) {
    return type >= KILOBOT_MESSAGE_SLEEP && type <= KILOBOT_MESSAGE_VOLTAGE;
}

/* Any CALIB or READUID but SAVE, which keeps only values being calibrated
 * (a stray one changes nothing), as with the classic library. */
static bool begins_calibrating(const uint8_t frame[KILOBOT_IR_FRAME_BYTES]) {
    uint8_t mode = frame[KILOBOT_CALIB_AT_MODE];
    return frame[OVERHEAD_TYPE_BYTE] == KILOBOT_MESSAGE_READUID ||
           (frame[OVERHEAD_TYPE_BYTE] == KILOBOT_MESSAGE_CALIB && mode >= KILOBOT_CALIB_UID &&
            mode <= KILOBOT_CALIB_STRAIGHT);
}

/* The battery's level when VOLTAGE came (a reading the IR receiver took
 * the ADC from is taken again). */
static uint8_t battery_light(void) {
    int16_t reading;
    while ((reading = kilobot_adc_read(KILOBOT_ADC_VOLTAGE)) < 0) {
    }
    return kilobot_battery_light(reading);
}

static uint8_t hold_light(void) {
    if (held == KILOBOT_MESSAGE_SLEEP || held == CALIBRATING) return KILOBOT_RGB(0, 0, 0);
    if (held == KILOBOT_MESSAGE_VOLTAGE) return battery_light();
    return HOLD_LIGHT;
}

/* The held robot: motors off, its light, the kernel with only the devices
 * (and the calibration's clock handler); the next system message that is
 * not the same request ends it. */
static void __attribute__((noreturn)) hold(void) {
    kilobot_motors_apply(0, 0);
    kilobot_led_apply(hold_light());
    if (held == CALIBRATING) overhead_calibration_start(calibration_request);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    for (;;) {
    }
}

void kilobot_overhead_control_start(void) {
    uint16_t mark = kilobot_restart_mark();
    uint8_t type = (uint8_t)mark;
    active = true;
    if ((mark & 0xFF00u) != OVERHEAD_HOLD_MARK || !(is_hold(type) || type == CALIBRATING)) return;
    held = type;
    hold();
}

/* The system message's action: a jump, or a request noted. */
static void act_on(const uint8_t frame[KILOBOT_IR_FRAME_BYTES]) {
    uint8_t type = frame[OVERHEAD_TYPE_BYTE];
    if (type == KILOBOT_MESSAGE_BOOT) kilobot_enter_bootloader();
    if (type == KILOBOT_MESSAGE_RESET) kilobot_restart(0);
    /* The controller repeats its message: the same request again changes
     * nothing. */
    if (type == KILOBOT_MESSAGE_RUN && held != 0) kilobot_restart(0);
    if (is_hold(type) && type != held) kilobot_restart(OVERHEAD_HOLD_MARK | type);
    if (held == CALIBRATING) {
        overhead_calibration_take(frame);
    } else if (begins_calibrating(frame)) {
        memcpy(calibration_request, frame, sizeof calibration_request);
        kilobot_restart(OVERHEAD_HOLD_MARK | CALIBRATING);
    }
}

bool kilobot_overhead_control_take(const uint8_t frame[KILOBOT_IR_FRAME_BYTES]) {
    if (!active || frame[OVERHEAD_TYPE_BYTE] < KILOBOT_MESSAGE_SYSTEM) return false;
    act_on(frame);
    return true;
}
