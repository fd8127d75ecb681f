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
 * for the held kernel (overhead_calibration.c). An app that takes the
 * messages as events (kilobot_overhead_control_start_events) gets them
 * instead while it runs, and the same actions when it hands them back. */
#include <string.h>

#include "openswarm/kernel.h"
#include "openswarm/kilobot.h"

#include "overhead_control_internal.h"

_Static_assert(sizeof(kilobot_ohc_message) == OVERHEAD_MESSAGE_BYTES, "the event carries the frame's first bytes");

#define HOLD_LIGHT KILOBOT_RGB(0, 0, 1) /* dim blue: held, awake */
#define CHARGE_FLASH_MS 1
#define CHARGE_DARK_MS 200
/* Calibrating, whether CALIB or READUID asked for it. */
#define CALIBRATING KILOBOT_MESSAGE_CALIB

static bool active;
static bool to_events; /* the app's: KILOBOT_EVENT_OHC while it runs */
static uint8_t held;   /* the hold's type, 0 while the app runs */
/* The request that began calibrating, for the run the restart begins. */
static uint8_t calibration_request[OVERHEAD_MESSAGE_BYTES] __attribute__((section(".noinit")));

static bool is_hold(uint8_t type) {
    return type >= KILOBOT_MESSAGE_SLEEP && type <= KILOBOT_MESSAGE_VOLTAGE;
}

/* Any CALIB or READUID but SAVE, which keeps only values being calibrated
 * (a stray one changes nothing), as with the classic library. */
static bool begins_calibrating(const uint8_t *frame) {
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
    if (held == KILOBOT_MESSAGE_SLEEP || held == KILOBOT_MESSAGE_CHARGE || held == CALIBRATING)
        return KILOBOT_RGB(0, 0, 0);
    if (held == KILOBOT_MESSAGE_VOLTAGE) return battery_light();
    return HOLD_LIGHT;
}

/* CHARGE, as kilolib shows it: a 1 ms dim red flash every 200 ms while
 * the charger charges, dark otherwise. From the tick, which the held
 * robot keeps for nothing else. */
static void show_charging(void) {
    static uint8_t ms;
    if (ms == 0 && kilobot_charging()) kilobot_led_apply(KILOBOT_RGB(1, 0, 0));
    if (ms == CHARGE_FLASH_MS) kilobot_led_apply(KILOBOT_RGB(0, 0, 0));
    ms = ms == CHARGE_FLASH_MS + CHARGE_DARK_MS - 1 ? 0 : ms + 1;
}

/* The held robot: motors off, its light, the kernel with only the devices
 * (and the calibration's clock handler); the next system message that is
 * not the same request ends it. */
static void __attribute__((noreturn)) hold(void) {
    kilobot_motors_apply(0, 0);
    kilobot_led_apply(hold_light());
    if (held == KILOBOT_MESSAGE_CHARGE) kilobot_tick_hook = show_charging;
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
static void act_on(const uint8_t *frame) {
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

/* BOOT and the bootloader's own messages are never the app's. */
static bool for_the_app(uint8_t type) { return to_events && held == 0 && type >= KILOBOT_MESSAGE_RESET; }

bool kilobot_overhead_control_take(const uint8_t frame[KILOBOT_IR_FRAME_BYTES]) {
    uint8_t type = frame[OVERHEAD_TYPE_BYTE];
    if (!active || type < KILOBOT_MESSAGE_SYSTEM) return false;
    if (for_the_app(type)) {
        Sys_Send_Event(KILOBOT_EVENT_OHC, frame, OVERHEAD_MESSAGE_BYTES); /* a full queue is counted */
    } else {
        act_on(frame);
    }
    return true;
}

sys_status kilobot_overhead_control_start_events(void) {
    sys_status st = Sys_Register_Event_Sized(KILOBOT_EVENT_OHC, OVERHEAD_MESSAGE_BYTES);
    if (st != SYS_OK) return st;
    to_events = true;
    kilobot_overhead_control_start();
    return SYS_OK;
}

void kilobot_overhead_control_act(const kilobot_ohc_message *message) {
    if (message != NULL && message->type >= KILOBOT_MESSAGE_SYSTEM) act_on((const uint8_t *)message);
}
