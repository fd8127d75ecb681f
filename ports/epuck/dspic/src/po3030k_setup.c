/* The PO3030K's registers for a frame (facts: GCtronic's e-puck library,
 * as ../README.md lists them). The sensor itself subsamples by 4 (its
 * QQVGA mode) or 2 (QVGA) when the zoom allows it; the line interrupt
 * takes every n-th of its pixels and rows for the rest. The sensor's
 * window starts one output pixel and one output row early: HREF must
 * come before the first wanted pixel (the interrupt's latency) and VSYNC
 * a row before the first wanted row. The window runs to the array's
 * right and bottom edges: the interrupt stops taking pixels and rows
 * itself. */
#include "po3030k_setup.h"

/* Registers (16-bit values high byte first, at reg and reg + 1). */
#define REG_SPEED 0x1Du
#define REG_SAMPLING 0x20u
#define REG_FORMAT 0x4Eu
#define REG_WINDOW_X1 0x08u
#define REG_WINDOW_Y1 0x0Au
#define REG_WINDOW_X2 0x0Cu
#define REG_WINDOW_Y2 0x0Eu
#define REG_VSYNC_START 0xA5u
#define REG_VSYNC_STOP 0xA7u
#define REG_VSYNC_COLUMN 0xA9u

#define FORMAT_RGB565 0x08u

/* The visible array starts at column 210, row 7 of the sensor's counts. */
#define ORIGIN_X 210u
#define ORIGIN_Y 7u

/* The line loop (camera_capture.s) takes a byte every 8 instruction
 * cycles: a pixel of 2 bytes is 16. */
#define LOOP_CYCLES_PER_PIXEL 16u

/* The sensor's subsampling, and the pixel clock divider that keeps its
 * output at a byte every 8 cycles of its 14.7456 MHz clock in RGB565. */
typedef struct mode {
    uint8_t factor, sampling, speed;
} mode;

static const mode modes[] = {
    {4u, 0x33u, 0x20u}, /* QQVGA, speed /4 */
    {2u, 0x11u, 0x30u}, /* QVGA, /8 */
    {1u, 0x44u, 0x40u}, /* VGA, /16 */
};

const po3030k_request po3030k_classifier_frame = {(PO3030K_ARRAY_WIDTH - 160u) / 2u,
                                                  (PO3030K_ARRAY_HEIGHT - 160u) / 2u, 160u, 160u, 8u};

static const mode *mode_for(uint8_t zoom) {
    unsigned i = 0;
    while (zoom % modes[i].factor != 0) i++; /* the last, factor 1, always fits */
    return &modes[i];
}

static bool fits(const po3030k_request *r) {
    if (r->zoom == 0 || r->width == 0 || r->height == 0) return false;
    if (r->width % r->zoom != 0 || r->height % r->zoom != 0) return false;
    if (r->width / r->zoom > 255u || r->height / r->zoom > 255u) return false;
    return (uint32_t)r->x + r->width <= PO3030K_ARRAY_WIDTH && (uint32_t)r->y + r->height <= PO3030K_ARRAY_HEIGHT;
}

static po3030k_write *pair(po3030k_write *w, uint8_t reg, uint16_t value) {
    w[0] = (po3030k_write){reg, (uint8_t)(value >> 8)};
    w[1] = (po3030k_write){(uint8_t)(reg + 1u), (uint8_t)(value & 0xFFu)};
    return w + 2;
}

bool po3030k_plan(const po3030k_request *request, po3030k_write writes[PO3030K_SETUP_WRITES],
                  po3030k_capture *capture) {
    if (!fits(request)) return false;
    const mode *m = mode_for(request->zoom);
    /* One output pixel (row) of lead; a window at the array's very edge has
     * its lead in the sensor's margin (ORIGIN_X, ORIGIN_Y > 4). */
    uint16_t x1 = (uint16_t)(ORIGIN_X + request->x - m->factor);
    uint16_t y1 = (uint16_t)(ORIGIN_Y + request->y - m->factor);
    po3030k_write *w = writes;
    *w++ = (po3030k_write){REG_FORMAT, FORMAT_RGB565};
    *w++ = (po3030k_write){REG_SAMPLING, m->sampling};
    *w++ = (po3030k_write){REG_SPEED, m->speed};
    w = pair(w, REG_WINDOW_X1, (uint16_t)(x1 - 1u)); /* the register counts from the column before */
    w = pair(w, REG_WINDOW_Y1, y1);
    w = pair(w, REG_WINDOW_X2, ORIGIN_X + PO3030K_ARRAY_WIDTH + 1u);
    w = pair(w, REG_WINDOW_Y2, ORIGIN_Y + PO3030K_ARRAY_HEIGHT + 1u);
    w = pair(w, REG_VSYNC_START, y1);
    w = pair(w, REG_VSYNC_STOP, ORIGIN_Y + PO3030K_ARRAY_HEIGHT);
    (void)pair(w, REG_VSYNC_COLUMN, (uint16_t)(x1 + 1u));
    uint8_t software = (uint8_t)(request->zoom / m->factor);
    capture->columns = (uint8_t)(request->width / request->zoom);
    capture->rows = (uint8_t)(request->height / request->zoom);
    capture->href_per_row = software;
    capture->skip_pixels = (uint8_t)(software - 1u);
    capture->delay_repeat = (uint16_t)(LOOP_CYCLES_PER_PIXEL * (software - 1u));
    return true;
}
