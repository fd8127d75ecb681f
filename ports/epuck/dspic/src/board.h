/* The e-puck board's parts, started by epuck_board_start (board_epuck.c). */
#ifndef BOARD_H
#define BOARD_H

void board_leds_init(void);       /* board_leds.c: the LED pins as outputs */
void board_steppers_init(void);   /* board_steppers.c: coil pins, timer priorities */
void board_proximity_start(void); /* board_proximity.c: 100 readings a second */
void board_selector_poll(void);   /* board_selector.c: from the tick */

#endif
