/* The frame being assembled from the camera's lines: plain C, no
 * hardware, tested on the host (tests/host/test_dspic_camera.cpp). The
 * line interrupt stores each row's bytes where camera_frame_row() says,
 * in the order they arrive (each pixel's high byte first), and reports
 * the row done; a VSYNC starts a frame. A frame delivered is whole; one
 * cut short by the next VSYNC is dropped and counted. */
#ifndef CAMERA_FRAME_H
#define CAMERA_FRAME_H

#include <stdbool.h>
#include <stdint.h>

#include "openswarm/epuck.h"

/* The classifier's 20 x 20 (800 bytes); nothing larger fits beside the
 * kernel in 8 KB. */
#define CAMERA_FRAME_MAX_PIXELS 400u

/* Called with each whole frame, from the line interrupt; the pixels are
 * the assembler's and stay valid until it returns. */
typedef void (*camera_frame_done)(const epuck_camera_frame *frame);

/* A frame of columns x rows pixels (at most CAMERA_FRAME_MAX_PIXELS) that
 * is the classifier's window `window` pixels wide (epuck_camera_frame);
 * false if it does not fit. Counters start at 0; no frame is under way
 * until the first VSYNC. */
bool camera_frame_init(uint8_t columns, uint8_t rows, uint16_t window, camera_frame_done done);

/* VSYNC: a new frame starts; one still short of its rows is dropped. */
void camera_frame_vsync(void);

/* Where the next row's 2 x columns bytes go, or NULL when no row is
 * wanted (before the first VSYNC, or the frame is complete). */
uint8_t *camera_frame_row(void);

/* The row at camera_frame_row() has its bytes: they become RGB565 pixels;
 * the last row hands the frame on. True while more rows are wanted. */
bool camera_frame_row_done(void);

uint16_t camera_frame_delivered(void);
uint16_t camera_frame_cut_short(void); /* frames dropped at a VSYNC */

#endif
