/* Shared by kilolib's files; not part of the API programs see. */
#ifndef KILOLIB_INTERNAL_H
#define KILOLIB_INTERNAL_H

#include <stdint.h>

#include "kilolib.h"
#include "openswarm/kernel.h"

/* kilolib.c. kilolib's own work to run as a handler, on the system stack;
 * the data is one byte, which work (kilolib_call). */
#define KILOLIB_EVENT_CALL ((sys_event_id)(SYS_EVENT_PORT_FIRST + 7))
enum kilolib_call {
    KILOLIB_TX_DUE /* the transmitter looks: kilo_message_tx() and the send */
};
/* Queue one (from the program it runs before the call returns). */
bool kilolib_call(uint8_t what);
void kilolib_program(void); /* the program: setup() the first time, then loop() for ever */
/* kilo_uid and the motor calibration (kilo_turn_left, ... and the motors'
 * kilobot_calib) as the EEPROM holds them. */
void kilolib_identity_load(void);
/* The program waits (at most ms): the CPU sleeps, handlers run, and the
 * transmitter's next look wakes it in time (tickless idle). */
void kilolib_wait(uint32_t ms);

/* The stack pointer now, and fn (which never returns) run afresh with the
 * stack pointer at sp and interrupts enabled: the frames above are
 * dropped (overhead_controller.c). The robot's SP register; the native
 * mode's own (ports/native). */
#ifdef __AVR__
#include <avr/interrupt.h>
#include <avr/io.h>
typedef uint16_t kilolib_sp;
static inline kilolib_sp kilolib_stack_pointer(void) { return SP; }
static inline void kilolib_run_afresh(kilolib_sp sp, void (*fn)(void)) {
    cli();
    SP = sp;
    sei();
    fn();
}
#else
#include "openswarm/native_stack.h"
typedef uintptr_t kilolib_sp;
#define kilolib_stack_pointer native_stack_pointer
#define kilolib_run_afresh native_run_afresh
#endif

/* overhead_controller.c. The robot does one thing at a time, named by the
 * system message that asked for it: RUN (the program), CALIB (a calibration
 * motion), VOLTAGE, CHARGE or WAKEUP (a status on the LED), SLEEP (nothing).
 * The activity runs on the system thread (main's stack), in place of the
 * kernel's idle loop: kilolib_run_activities, for ever. */
typedef void (*kilolib_activity_fn)(void);
void kilolib_system_message(const message_t *msg);
/* Whether this run began with RESET (asked once: the answer is then false). */
bool kilolib_restarted(void);
uint8_t kilolib_activity(void);
/* The current activity ends (motors off, LED dark: at once; its code at its
 * next kilolib call, kilolib_stop_point) and fn, if any, runs next. */
void kilolib_activity_start(uint8_t activity, kilolib_activity_fn fn);
/* The system thread's program (Sys_Run_SystemProgram): the activities. */
void kilolib_run_activities(void);
/* Where an activity that was replaced stops: the kilolib calls it makes
 * (delay, set_color, set_motors) leave it for the next. Nothing elsewhere
 * (a handler, a thread of the app's). */
void kilolib_stop_point(void);

/* calibration.c: CALIB and READUID */
void kilolib_calibration_message(const message_t *msg);

/* status_lights.c: the LED pattern of the current activity, for ever */
void kilolib_status_lights(void);

#endif
