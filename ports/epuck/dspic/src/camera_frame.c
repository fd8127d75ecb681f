/* The camera's frame assembly (camera_frame.h). Bytes are stored as they
 * come and turned into pixels a row at a time, in place, when the row is
 * done: between two rows the line interrupt has the sensor's blanking and
 * the skipped lines, thousands of cycles, while inside a row it has 8
 * cycles a byte and no time to combine them. */
#include "camera_frame.h"

#include <stddef.h>

static union {
    uint16_t pixels[CAMERA_FRAME_MAX_PIXELS];
    uint8_t bytes[CAMERA_FRAME_MAX_PIXELS * 2u];
} memory;

static epuck_camera_frame frame = {memory.pixels, 0, 0, 0};
static camera_frame_done frame_done;
static uint8_t row;         /* rows done in the frame under way */
static bool under_way;      /* a VSYNC has started a frame not yet whole */
static uint16_t delivered, cut_short;

bool camera_frame_init(uint8_t columns, uint8_t rows, uint16_t window, camera_frame_done done) {
    if (columns == 0 || rows == 0 || (unsigned)columns * rows > CAMERA_FRAME_MAX_PIXELS) return false;
    frame.width = columns;
    frame.height = rows;
    frame.window = window;
    frame_done = done;
    row = 0;
    under_way = false;
    delivered = 0;
    cut_short = 0;
    return true;
}

void camera_frame_vsync(void) {
    if (under_way) cut_short++;
    under_way = true;
    row = 0;
}

uint8_t *camera_frame_row(void) {
    if (!under_way) return NULL;
    return &memory.bytes[(unsigned)row * frame.width * 2u];
}

/* Each pixel's two bytes, high first as the sensor sends them, read before
 * its halfword is written. */
static void to_rgb565(uint16_t *pixels, unsigned count) {
    const uint8_t *b = (const uint8_t *)pixels;
    for (unsigned i = 0; i < count; i++)
        pixels[i] = (uint16_t)((unsigned)b[2u * i] << 8 | b[2u * i + 1u]);
}

bool camera_frame_row_done(void) {
    if (!under_way) return false;
    to_rgb565(&memory.pixels[(unsigned)row * frame.width], frame.width);
    if (++row < frame.height) return true;
    under_way = false;
    delivered++;
    if (frame_done != NULL) frame_done(&frame);
    return false;
}

uint16_t camera_frame_delivered(void) { return delivered; }
uint16_t camera_frame_cut_short(void) { return cut_short; }
