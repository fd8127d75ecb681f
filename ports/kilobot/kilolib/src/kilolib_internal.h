/* Shared by kilolib's files; not part of the API programs see. */
#ifndef KILOLIB_INTERNAL_H
#define KILOLIB_INTERNAL_H

#include <stdint.h>

#include "kilolib.h"
#include "openswarm/kernel.h"

/* kilolib.c. Data: one byte, which transmit callback to run (the
 * transmitter thread sends it, the handler runs it on the system stack). */
#define KILOLIB_EVENT_TX ((sys_event_id)(SYS_EVENT_PORT_FIRST + 7))
void kilolib_program(void *arg); /* the program: setup(), then loop() for ever */
/* kilo_uid and the motor calibration (kilo_turn_left, ... and the motors'
 * kilobot_calib) as the EEPROM holds them. */
void kilolib_identity_load(void);

/* overhead_controller.c. The robot does one thing at a time, named by the
 * system message that asked for it: RUN (the program), CALIB (a calibration
 * motion), VOLTAGE, CHARGE or WAKEUP (a status on the LED), SLEEP (nothing). */
void kilolib_system_message(const message_t *msg);
uint8_t kilolib_activity(void);
/* The current activity ends (its thread killed, motors off, LED dark) and
 * fn, if any, starts in a thread of its own. */
void kilolib_activity_start(uint8_t activity, sys_process_fn fn);

/* calibration.c: CALIB and READUID */
void kilolib_calibration_message(const message_t *msg);

/* status_lights.c: the LED pattern of the current activity, for ever */
void kilolib_status_lights(void *arg);

#endif
