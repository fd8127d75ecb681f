/* The PO3030K's set-up for a frame, computed without touching hardware:
 * the registers to write over I2C and the capture plan the line interrupt
 * follows. Plain C, tested on the host (tests/host/test_dspic_camera.cpp)
 * against a model of the sensor. Facts and their sources: ../README.md. */
#ifndef PO3030K_SETUP_H
#define PO3030K_SETUP_H

#include <stdbool.h>
#include <stdint.h>

/* 7-bit address (0xDC on the bus to write), and the identity registers. */
#define PO3030K_ADDRESS 0x6Eu
#define PO3030K_REG_ID_HIGH 0x00u
#define PO3030K_REG_ID_LOW 0x01u
#define PO3030K_ID 0x3030u /* a PO6030K answers 0x6030: not handled */

#define PO3030K_ARRAY_WIDTH 640u
#define PO3030K_ARRAY_HEIGHT 480u

/* What the frame is: a window of the array (its top-left corner and size
 * in array pixels) taken every `zoom` pixels both ways, RGB565. */
typedef struct po3030k_request {
    uint16_t x, y, width, height;
    uint8_t zoom;
} po3030k_request;

typedef struct po3030k_write {
    uint8_t reg, value;
} po3030k_write;

/* What the line interrupt does with what the sensor sends once set up:
 * after VSYNC, every `href_per_row`-th line (counted by Timer4 on HREF)
 * is a row; in it, after HREF, `columns` pixels of 2 bytes each are
 * taken with `skip_pixels` of the sensor's output skipped after each,
 * waiting `delay_repeat` + 1 NOPs between them (camera_capture.s). */
typedef struct po3030k_capture {
    uint8_t columns, rows;
    uint8_t href_per_row;
    uint8_t skip_pixels;
    uint16_t delay_repeat;
} po3030k_capture;

#define PO3030K_SETUP_WRITES 17u

/* The classifier's frame: the central 160 x 160, every 8th pixel: 20 x 20. */
extern const po3030k_request po3030k_classifier_frame;

/* False if the request cannot be met: a zoom of 0, a size not a multiple
 * of it, a window outside the array, or a frame over 255 columns or rows. */
bool po3030k_plan(const po3030k_request *request, po3030k_write writes[PO3030K_SETUP_WRITES],
                  po3030k_capture *capture);

#endif
