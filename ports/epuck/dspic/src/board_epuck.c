/* The e-puck (dsPIC30F6014A) board behind epuck_board.h: starts the LEDs,
 * the steppers, the proximity rounds and the selector's reading, and, in
 * a build with the camera (board.h: it takes the steppers' timers), the
 * camera, whose frames become EPUCK_EVENT_CAMERA. */
#include "board.h"
#include "dspic_port.h"
#include "../../src/epuck_board.h"

void epuck_board_start(void) {
    board_leds_init();
    board_steppers_init();
    board_proximity_start();
    dspic_tick_hook = board_selector_poll;
#if EPUCK_DSPIC_CAMERA
    (void)board_camera_start(); /* says on the console if it failed */
#endif
}
