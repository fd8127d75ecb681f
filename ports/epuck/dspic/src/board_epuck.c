/* The e-puck (dsPIC30F6014A) board behind epuck_board.h: starts the LEDs,
 * the steppers, the proximity rounds, the selector's reading and the
 * camera, whose frames become EPUCK_EVENT_CAMERA. */
#include "board.h"
#include "dspic_port.h"
#include "../../src/epuck_board.h"

/* From the tick interrupt, inside the kernel's bracket. */
static void board_tick(void) {
    board_selector_poll();
#if EPUCK_DSPIC_CAMERA
    board_camera_poll();
#endif
}

void epuck_board_start(void) {
    board_leds_init();
    board_steppers_init();
    board_proximity_start();
    dspic_tick_hook = board_tick;
#if EPUCK_DSPIC_CAMERA
    (void)board_camera_start(); /* says on the console if it failed */
#endif
}
