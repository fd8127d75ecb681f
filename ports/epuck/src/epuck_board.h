/* The lower layer each e-puck board supplies to the device layer
 * (ports/epuck/src): the e-puck2's drivers, the QEMU board, the dsPIC's.
 * Outputs are called from the kernel's system thread (the devices' write
 * functions); inputs come back from the board's interrupts or threads
 * through the epuck_*_arrived functions, bracketed for the kernel
 * (os_isr_enter/exit or the port's equivalent) when called from an
 * interrupt. */
#ifndef EPUCK_BOARD_H
#define EPUCK_BOARD_H

#include <stdbool.h>
#include <stdint.h>

#include "openswarm/epuck.h"

/* ---- outputs ---- */
void epuck_board_set_wheels(int16_t left, int16_t right); /* steps/s, limited already */
void epuck_board_set_ring_leds(uint8_t mask);
void epuck_board_set_body_led(bool on);
void epuck_board_set_front_led(bool on);
void epuck_board_set_rgb_leds(uint8_t rgb); /* EPUCK_RGB */

/* Start sampling what the board has: proximity (100 times a second),
 * camera frames, the selector. Called once the devices are registered. */
void epuck_board_start(void);

/* ---- inputs, from the board ---- */
void epuck_proximity_arrived(const epuck_proximity_samples *samples);
void epuck_camera_arrived(const epuck_camera_frame *frame);
void epuck_selector_arrived(uint8_t position); /* as often as it is read: changes are events */

#endif
