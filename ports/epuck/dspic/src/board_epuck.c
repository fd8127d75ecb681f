/* The e-puck (dsPIC30F6014A) board behind epuck_board.h: starts the LEDs,
 * the steppers, the proximity rounds and the selector's reading. The
 * camera is not written (README.md says why): no frame ever arrives, so
 * EPUCK_EVENT_CAMERA is registered and never sent. */
#include "board.h"
#include "dspic_port.h"
#include "../../src/epuck_board.h"

void epuck_board_start(void) {
    board_leds_init();
    board_steppers_init();
    board_proximity_start();
    dspic_tick_hook = board_selector_poll;
}
