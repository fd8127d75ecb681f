/* The camera's virtual sensor (the paper's case study): what is in front
 * of the robot, from the centre of a frame.
 *
 * The original controller (Gauci et al. 2014, as the OpenSwarm paper
 * runs it) takes the central 160 x 160 pixels of a 640 x 480 frame, zoomed
 * down 8 times to 20 x 20, samples 24 of those pixels and matches each to
 * dark, green (another robot), red (an object) or white (a wall); 2 or more
 * red or dark: an object; else 2 or more green: a robot; else nothing.
 * Which 24 it samples is not published: here, the 4 middle rows of the
 * 20 x 20 grid at every third column from the second (6 x 4), a band
 * across the line of sight. A smaller frame's window is the same share of
 * it (a quarter of its width, square), unless the frame says its window
 * (the dsPIC e-puck's frame is the window alone, 20 x 20). */
#include "openswarm/epuck.h"

#define GRID 20u
#define SAMPLE_COLUMNS 6u
#define SAMPLE_ROWS 4u

/* Channels of an RGB565 pixel, each scaled to 0..255. */
epuck_colour epuck_colour_of(uint16_t rgb565) {
    unsigned r = ((rgb565 >> 11) & 0x1Fu) * 255u / 31u;
    unsigned g = ((rgb565 >> 5) & 0x3Fu) * 255u / 63u;
    unsigned b = (rgb565 & 0x1Fu) * 255u / 31u;
    unsigned top = r > g ? (r > b ? r : b) : (g > b ? g : b);
    unsigned bottom = r < g ? (r < b ? r : b) : (g < b ? g : b);
    if (top < 64u) return EPUCK_COLOUR_DARK;
    if (bottom > 160u) return EPUCK_COLOUR_WHITE;
    if (r > 80u && r > 2u * g && r > 2u * b) return EPUCK_COLOUR_RED;
    if (g > 80u && g > 2u * r && g > 2u * b) return EPUCK_COLOUR_GREEN;
    return EPUCK_COLOUR_OTHER;
}

bool epuck_classify_frame(const epuck_camera_frame *f, epuck_seen *seen) {
    uint16_t window = f->window != 0 ? f->window : (uint16_t)(f->width / 4u);
    if (f->pixels == NULL || f->width < GRID || window > f->width || window > f->height) return false;
    uint16_t x0 = (uint16_t)((f->width - window) / 2u), y0 = (uint16_t)((f->height - window) / 2u);
    unsigned red_or_dark = 0, green = 0;
    for (unsigned row = 0; row < SAMPLE_ROWS; row++) {
        unsigned gy = GRID / 2u - SAMPLE_ROWS / 2u + row; /* rows 8..11 */
        unsigned y = y0 + (gy * window + window / 2u) / GRID;
        for (unsigned column = 0; column < SAMPLE_COLUMNS; column++) {
            unsigned gx = 2u + 3u * column; /* columns 2, 5, ..., 17 */
            unsigned x = x0 + (gx * window + window / 2u) / GRID;
            epuck_colour c = epuck_colour_of(f->pixels[(unsigned long)y * f->width + x]);
            if (c == EPUCK_COLOUR_RED || c == EPUCK_COLOUR_DARK) red_or_dark++;
            if (c == EPUCK_COLOUR_GREEN) green++;
        }
    }
    *seen = red_or_dark >= 2u ? EPUCK_SEEN_OBJECT : green >= 2u ? EPUCK_SEEN_ROBOT : EPUCK_SEEN_NOTHING;
    return true;
}

uint8_t epuck_camera_classifier(sys_device *dev, const void *in, uint8_t size, void *out,
                                uint8_t capacity) {
    (void)dev;
    epuck_seen seen;
    if (size != sizeof(epuck_camera_frame) || capacity < 1 || !epuck_classify_frame(in, &seen)) return 0;
    *(uint8_t *)out = (uint8_t)seen;
    return 1;
}
