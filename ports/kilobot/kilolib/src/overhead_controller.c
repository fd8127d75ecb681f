/* The overhead controller's system messages (types from 0x80), handled as
 * the classic Kilobot library documents them. Each asks the robot for one
 * activity, which replaces the one before. */
#include "kilolib_internal.h"
#include "openswarm/kilobot.h"
#include "openswarm/kilobot_sim.h"

#ifndef KILOLIB_LOOP_STACK
#define KILOLIB_LOOP_STACK 192 /* bytes for setup() and loop(), beyond the port's frame */
#endif

static uint8_t activity;
static sys_pid activity_pid = SYS_PID_NONE;

uint8_t kilolib_activity(void) { return activity; }

static sys_process_fn activity_fn; /* the thread the current activity runs, if any */

/* The current activity ends (its thread killed, motors off, LED dark) and
 * the new one's thread, if any, starts once the old thread is reaped:
 * every activity gets the program's stack size, so the old thread's slot
 * and stack are the ones it reuses (they are not free before). */
void kilolib_activity_start(uint8_t what, sys_process_fn fn) {
    if (activity_pid != SYS_PID_NONE) {
        Sys_Kill_Process(activity_pid); /* SYS_E_INVALID if it had ended: nothing to kill */
        activity_pid = SYS_PID_NONE;
        /* Sent as events, after whatever the killed thread still had queued. */
        set_motors(0, 0);
        set_color(0);
    }
    activity = what;
    activity_fn = fn;
    /* A full event queue (counted in event_queue_full): start it now, which
     * works unless the old thread still holds the only slot. */
    if (fn != 0 && !kilolib_call(KILOLIB_START_ACTIVITY)) kilolib_activity_thread_start();
}

void kilolib_activity_thread_start(void) {
    if (activity_fn != 0 && activity_pid == SYS_PID_NONE &&
        Sys_Start_Process_Ex(activity_fn, 0, KILOLIB_LOOP_STACK, 0, &activity_pid) == SYS_OK)
        sim_thread_name(activity_pid, PSTR("kilolib program (setup, loop)"));
}

/* The same request again (the overhead controller repeats its messages)
 * leaves the activity running undisturbed. */
static void activity_switch(uint8_t what, sys_process_fn fn) {
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
