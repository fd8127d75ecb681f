/* The overhead controller's system messages (types from 0x80), handled as
 * the classic Kilobot library documents them. Each asks the robot for one
 * activity, which replaces the one before. */
#include <avr/interrupt.h>
#include <avr/io.h>

#include "kilolib_internal.h"
#include "openswarm/kilobot.h"

#ifndef KILOLIB_LOOP_STACK
#define KILOLIB_LOOP_STACK 192 /* bytes for setup() and loop(), beyond the port's frame */
#endif

/* The Kilobot's IR bootloader lives in the ATmega328P's 4 KB boot section,
 * from byte address 0x7000 to the end of the flash. */
#define BOOTLOADER_ADDRESS 0x7000

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
    if (activity_fn != 0 && activity_pid == SYS_PID_NONE)
        Sys_Start_Process_Ex(activity_fn, 0, KILOLIB_LOOP_STACK, 0, &activity_pid);
}

/* The same request again (the overhead controller repeats its messages)
 * leaves the activity running undisturbed. */
static void activity_switch(uint8_t what, sys_process_fn fn) {
    if (activity != what) kilolib_activity_start(what, fn);
}

/* BOOT: the bootloader takes the robot over to receive a new program.
 * It sets up the timers and interrupts it uses itself, but an interrupt of
 * ours left enabled and pending (the IR input capture) would enter its
 * vector table, where no handler expects it: ours are masked and cleared. */
static void __attribute__((noreturn)) bootloader_jump(void) {
    cli();
    kilobot_motors_apply(0, 0);
    TIMSK0 = 0;
    TIMSK1 = 0;
    TIFR0 = _BV(OCF0B) | _BV(OCF0A) | _BV(TOV0); /* flags clear when written 1 */
    TIFR1 = _BV(ICF1) | _BV(OCF1B) | _BV(OCF1A) | _BV(TOV1);
    __asm__ __volatile__("jmp %0" ::"i"(BOOTLOADER_ADDRESS)); /* a byte address, to the assembler */
    __builtin_unreachable();
}

void kilolib_system_message(const message_t *msg) {
    switch (msg->type) {
    case BOOT:
        bootloader_jump();
    case RESET: /* the classic library restarts: calibration reread, waiting for RUN */
        kilolib_identity_load();
        activity_switch(WAKEUP, kilolib_status_lights);
        break;
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
