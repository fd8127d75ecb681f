/* The overhead controller's system messages for apps on the OpenSwarm API
 * (kilobot.h): what KiloGUI's buttons do to a robot, whatever the app.
 *
 * A hold (SLEEP, WAKEUP, CHARGE, VOLTAGE) is a restart with a mark: the
 * app's main() runs up to robot_devices_init(), which sees the mark and
 * runs the kernel with the devices alone, so nothing of the app runs and
 * everything of it starts afresh at RUN, as a kilolib program's setup()
 * does. The actions are taken where the frame is checked, in the IR
 * interrupt: each is a jump that needs nothing of the kernel. */
#include "openswarm/kernel.h"
#include "openswarm/kilobot.h"

#define TYPE_BYTE 9u
/* The overhead controller's types (the classic library's message.h). */
enum { BOOT = 0x80, BOOTPGM_PAGE, BOOTPGM_SIZE, RESET, SLEEP, WAKEUP, CHARGE, VOLTAGE, RUN };
/* A restart that holds: this, with the message's type in its low byte. */
#define HOLD_MARK 0x4800u
#define HOLD_LIGHT KILOBOT_RGB(0, 0, 1) /* dim blue: held, awake */

static bool active;
static uint8_t held; /* the hold's type, 0 while the app runs */

static bool is_hold(uint8_t type) {
    return type == SLEEP || type == WAKEUP || type == CHARGE || type == VOLTAGE;
}

/* The held robot: motors off, its light, the kernel with only the
 * devices; the next system message ends it. */
static void __attribute__((noreturn)) hold(void) {
    uint8_t light = held == SLEEP ? KILOBOT_RGB(0, 0, 0) : HOLD_LIGHT;
    kilobot_motors_apply(0, 0);
    kilobot_led_apply(light);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    for (;;) {
    }
}

void kilobot_overhead_control_start(void) {
    uint16_t mark = kilobot_restart_mark();
    active = true;
    if ((mark & 0xFF00u) != HOLD_MARK || !is_hold((uint8_t)mark)) return;
    held = (uint8_t)mark;
    hold();
}

bool kilobot_overhead_control_take(const uint8_t frame[KILOBOT_IR_FRAME_BYTES]) {
    uint8_t type = frame[TYPE_BYTE];
    if (!active || type < KILOBOT_MESSAGE_SYSTEM) return false;
    if (type == BOOT) kilobot_enter_bootloader();
    if (type == RESET) kilobot_restart(0);
    /* The controller repeats its message: the same request again changes
     * nothing. */
    if (type == RUN && held != 0) kilobot_restart(0);
    if (is_hold(type) && type != held) kilobot_restart(HOLD_MARK | type);
    return true;
}
