/* Shared by kilolib's files; not part of the API programs see. */
#ifndef KILOLIB_INTERNAL_H
#define KILOLIB_INTERNAL_H

#include <stdint.h>

#include "kilolib.h"
#include "openswarm/kernel.h"

/* kilolib.c. kilolib's own work to run as a handler, on the system stack
 * and after any thread ended before it is reaped; the data is one byte,
 * which work (kilolib_call). */
#define KILOLIB_EVENT_CALL ((sys_event_id)(SYS_EVENT_PORT_FIRST + 7))
enum kilolib_call {
    KILOLIB_TX_DUE,        /* kilo_message_tx() */
    KILOLIB_TX_SENT,       /* kilo_message_tx_success() */
    KILOLIB_START_ACTIVITY /* the thread of the activity kilolib_activity_start asked for */
};
/* Queue one (from a thread it runs before the call returns). */
bool kilolib_call(uint8_t what);
void kilolib_program(void *arg); /* the program: setup() the first time, then loop() for ever */
/* kilo_uid and the motor calibration (kilo_turn_left, ... and the motors'
 * kilobot_calib) as the EEPROM holds them. */
void kilolib_identity_load(void);

/* overhead_controller.c. The robot does one thing at a time, named by the
 * system message that asked for it: RUN (the program), CALIB (a calibration
 * motion), VOLTAGE, CHARGE or WAKEUP (a status on the LED), SLEEP (nothing). */
void kilolib_system_message(const message_t *msg);
/* Whether this run began with RESET (asked once: the answer is then false). */
bool kilolib_restarted(void);
uint8_t kilolib_activity(void);
/* The current activity ends (its thread killed, motors off, LED dark) and
 * fn, if any, starts in a thread of its own once the old thread is reaped
 * (kilolib_activity_thread_start, through KILOLIB_START_ACTIVITY). */
void kilolib_activity_start(uint8_t activity, sys_process_fn fn);
void kilolib_activity_thread_start(void);

/* calibration.c: CALIB and READUID */
void kilolib_calibration_message(const message_t *msg);

/* status_lights.c: the LED pattern of the current activity, for ever */
void kilolib_status_lights(void *arg);

#endif
