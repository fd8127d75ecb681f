/* The e-puck board's parts, started by epuck_board_start (board_epuck.c). */
#ifndef BOARD_H
#define BOARD_H

#include <stdbool.h>

void board_leds_init(void);       /* board_leds.c: the LED pins as outputs */
void board_steppers_init(void);   /* board_steppers.c: coil pins, timer priorities */
void board_proximity_start(void); /* board_proximity.c: 100 readings a second */
void board_selector_poll(void);   /* board_selector.c: from the tick */

/* The camera (on unless EPUCK_DSPIC_CAMERA is 0, e.g. -D on the compiler's
 * command line, for an app that needs neither it nor the 10% of the CPU
 * its rows take): Timer4 and Timer5 count its lines and frames (their
 * clock inputs are HREF and VSYNC); the steppers use Timer3. */
#ifndef EPUCK_DSPIC_CAMERA
#define EPUCK_DSPIC_CAMERA 1
#endif
/* board_camera.c: the sensor reset and set up over I2C, frames captured;
 * false (and a line on the console) if it did not answer as a PO3030K.
 * board_camera_poll, from the tick: a whole frame to the device layer. */
bool board_camera_start(void);
void board_camera_poll(void);

#endif
