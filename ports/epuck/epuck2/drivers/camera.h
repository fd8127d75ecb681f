/* The e-puck2's camera: the PO8030's frames (160 x 120, RGB565) taken by
 * the DCMI into RAM through DMA2 stream 1, one at a time, each handed on
 * from the DMA's transfer-complete interrupt. */
#ifndef EPUCK2_CAMERA_H
#define EPUCK2_CAMERA_H

#include <stdbool.h>
#include <stdint.h>

#include "openswarm/epuck.h"

/* Called from the DMA's interrupt with each whole frame; the pixels are
 * the driver's and stay valid until it returns (the next frame is taken
 * into the same memory once it has). */
typedef void (*epuck2_camera_frame_done)(const epuck_camera_frame *frame);

/* The sensor set up over I2C (epuck2_i2c_init first), then the capture
 * started. False if the sensor did not take its set-up: nothing started. */
bool epuck2_camera_init(epuck2_camera_frame_done on_frame);

/* Frames lost to a DCMI overrun or error or a DMA error, since init. */
uint32_t epuck2_camera_frames_dropped(void);

void DMA2_Stream1_IRQHandler(void);
void DCMI_IRQHandler(void);

#ifdef EPUCK2_REGISTER_MODEL
/* The memory the DMA fills: the test writes there what the sensor sent. */
uint8_t *epuck2_camera_model_dma_memory(void);
#endif

#endif
