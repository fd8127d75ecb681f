/* The e-puck board's parts, started by epuck_board_start (board_epuck.c). */
#ifndef BOARD_H
#define BOARD_H

#include <stdbool.h>

void board_leds_init(void);       /* board_leds.c: the LED pins as outputs */
void board_steppers_init(void);   /* board_steppers.c: coil pins, timer priorities */
void board_proximity_start(void); /* board_proximity.c: 100 readings a second */
void board_selector_poll(void);   /* board_selector.c: from the tick */

/* The camera needs Timer4 and Timer5 (their clock inputs are HREF and
 * VSYNC), which the steppers use: a build has one or the other until the
 * steppers move to another timer. EPUCK_DSPIC_CAMERA 1 (e.g. -D on the
 * compiler's command line) starts the camera and leaves the wheels
 * released. */
#ifndef EPUCK_DSPIC_CAMERA
#define EPUCK_DSPIC_CAMERA 0
#endif
/* board_camera.c: the sensor reset and set up over I2C, frames captured;
 * false (and a line on the console) if it did not answer as a PO3030K. */
bool board_camera_start(void);

#endif
