/* The overhead controller's system messages (types from 0x80), handled as
 * the classic Kilobot library documents them. Each asks the robot for one
 * activity, which replaces the one before. Activities run on the system
 * thread, on main()'s stack, as the classic library's main loop runs them:
 * no thread, no stack of their own. */
#include <util/atomic.h>

#include "kilolib_internal.h"
#include "openswarm/kilobot.h"

static uint8_t activity;
static kilolib_activity_fn activity_fn; /* what the current activity runs, if anything */
/* Activities started so far, and which of them runs (both mod 256): they
 * differ once the running one is replaced. */
static uint8_t started, running;
/* The stack pointer where the activities' loop begins: a replaced
 * activity's code goes back there, its frames dropped as a killed thread's
 * stack would be. (setjmp would keep 23 bytes of registers for it; the
 * loop needs none, it starts afresh.) */
static kilolib_sp activities_sp;

uint8_t kilolib_activity(void) { return activity; }

/* From a handler (a system message): the current activity ends, motors
 * off and LED dark at once (sent as events, after whatever it still had
 * queued); its code stops at its next kilolib call (kilolib_stop_point). */
void kilolib_activity_start(uint8_t what, kilolib_activity_fn fn) {
    if (activity_fn != 0) {
        set_motors(0, 0);
        set_color(0);
    }
    activity = what;
    activity_fn = fn;
    started++;
}

static void __attribute__((noreturn)) run_activities(void);

void kilolib_stop_point(void) {
    if (started == running || !Sys_In_SystemProgram()) return;
    kilolib_run_afresh(activities_sp, run_activities);
}

/* The system thread's program: the current activity's code, once per
 * start (the calibration motion returns; the program and the status lights
 * never do); waiting for the next start meanwhile. */
static void run_activities(void) {
    for (;;) {
        uint8_t n;
        kilolib_activity_fn fn;
        ATOMIC_BLOCK(ATOMIC_RESTORESTATE) {
            n = started;
            fn = activity_fn;
        }
        bool fresh = n != running;
        running = n;
        if (fresh && fn != 0)
            fn();
        else
            kilolib_wait(UINT32_MAX); /* until a system message starts another */
    }
}

void kilolib_run_activities(void) {
    activities_sp = kilolib_stack_pointer();
    run_activities();
}

/* The same request again (the overhead controller repeats its messages)
 * leaves the activity running undisturbed. */
static void activity_switch(uint8_t what, kilolib_activity_fn fn) {
    if (activity != what) kilolib_activity_start(what, fn);
}

/* RESET: the program starts over from scratch, as the classic library's
 * jump to address 0 does: the C runtime sets the stack and every static
 * afresh (the kernel's state, kilo_ticks, the program's own), main() runs
 * kilo_init and kilo_start, and the robot waits for RUN, which runs setup()
 * (kilobot_restart puts the peripherals back as at power-up first). */
#define RESTART_MARK 0x5A3Cu

bool kilolib_restarted(void) { return kilobot_restart_mark() == RESTART_MARK; }

void kilolib_system_message(const message_t *msg) {
    switch (msg->type) {
    case BOOT:
        kilobot_enter_bootloader();
    case RESET:
        kilobot_restart(RESTART_MARK);
    case SLEEP:
        activity_switch(SLEEP, 0);
        break;
    case WAKEUP:
    case CHARGE:
    case VOLTAGE:
        activity_switch(msg->type, kilolib_status_lights);
        break;
    case RUN:
        activity_switch(RUN, kilolib_program);
        break;
    case CALIB:
    case READUID:
        kilolib_calibration_message(msg);
        break;
    default:
        break; /* BOOTPGM_PAGE, BOOTPGM_SIZE: for the bootloader */
    }
}
