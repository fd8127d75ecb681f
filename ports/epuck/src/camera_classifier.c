/* The camera's virtual sensor (the paper's case study): what is in front
 * of the robot, from the centre of a frame.
 *
 * The original controller (Gauci et al. 2014, as the OpenSwarm paper runs
 * it) takes the central 160 x 160 pixels of a 640 x 480 frame, zoomed down
 * 8 times to 20 x 20, samples 24 of those pixels and matches each to dark,
 * green (another robot), red (an object) or white (a wall); 2 or more red
 * or dark: an object; else 2 or more green: a robot; else nothing.
 *
 * Which 24, and how a pixel is matched, the original OpenSwarm sources say
 * (system_IO_camera.c at a83c65e, os/platform/e-puck/camera.c at HEAD, and
 * camera_processing.c beside them): x = 6, 9, 12, 15 by y = 4, 6, ..., 14
 * of the 20 x 20 frame, x the column; each pixel's 8-bit channels (RGB565
 * shifted up, low bits zero) go to the nearest of dark (0, 0, 0), green
 * (0, 40, 0), red (80, 0, 0) and white (100, 80, 80), the sum of the
 * channels' absolute differences, a tie to the first of those four.
 * The columns run across the robot's view, left to right: the original
 * drives the PO6030 (its registers are written by name), which the e-puck
 * library reports mounted horizontally, 640 x 480, and sets mirrored both
 * ways (e_poxxxx_init_cam, e_poxxxx_get_orientation in the library's
 * e_common.c) - the sensor sits upside down, the two mirrors right it.
 *
 * Built with EPUCK_CLASSIFIER_BAND, the classifier is this project's
 * earlier guess instead: the 4 middle rows at every third column from the
 * second (6 x 4, columns 2..17, about 1.6 times wider) and fixed colour
 * thresholds (epuck_colour_of).
 *
 * A smaller frame's window is the same share of it (a quarter of its
 * width, square), unless the frame says its window (the dsPIC e-puck's
 * frame is the window alone, 20 x 20). */
#include "openswarm/epuck.h"

#define GRID 20u

#ifdef EPUCK_CLASSIFIER_BAND
static const uint8_t sample_columns[] = {2, 5, 8, 11, 14, 17};
static const uint8_t sample_rows[] = {8, 9, 10, 11};
#define COLOUR_OF epuck_colour_of
#else
static const uint8_t sample_columns[] = {6, 9, 12, 15};
static const uint8_t sample_rows[] = {4, 6, 8, 10, 12, 14};
#define COLOUR_OF epuck_colour_nearest
#endif
#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

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

static unsigned distance(unsigned a, unsigned b) { return a > b ? a - b : b - a; }

epuck_colour epuck_colour_nearest(uint16_t rgb565) {
    /* The original's references, in its order of preference on a tie. */
    static const struct {
        uint8_t r, g, b;
        epuck_colour colour;
    } reference[] = {{0, 0, 0, EPUCK_COLOUR_DARK},
                     {0, 40, 0, EPUCK_COLOUR_GREEN},
                     {80, 0, 0, EPUCK_COLOUR_RED},
                     {100, 80, 80, EPUCK_COLOUR_WHITE}};
    unsigned r = ((rgb565 >> 11) & 0x1Fu) << 3, g = ((rgb565 >> 5) & 0x3Fu) << 2, b = (rgb565 & 0x1Fu) << 3;
    epuck_colour best = EPUCK_COLOUR_DARK;
    unsigned nearest = ~0u;
    for (unsigned k = 0; k < COUNT(reference); k++) {
        unsigned d = distance(r, reference[k].r) + distance(g, reference[k].g) + distance(b, reference[k].b);
        if (d < nearest) {
            nearest = d;
            best = reference[k].colour;
        }
    }
    return best;
}

bool epuck_classify_frame(const epuck_camera_frame *f, epuck_seen *seen) {
    uint16_t window = f->window != 0 ? f->window : (uint16_t)(f->width / 4u);
    if (f->pixels == NULL || f->width < GRID || window > f->width || window > f->height) return false;
    uint16_t x0 = (uint16_t)((f->width - window) / 2u), y0 = (uint16_t)((f->height - window) / 2u);
    unsigned red_or_dark = 0, green = 0;
    for (unsigned row = 0; row < COUNT(sample_rows); row++) {
        unsigned y = y0 + (sample_rows[row] * window + window / 2u) / GRID;
        for (unsigned column = 0; column < COUNT(sample_columns); column++) {
            unsigned x = x0 + (sample_columns[column] * window + window / 2u) / GRID;
            epuck_colour c = COLOUR_OF(f->pixels[(unsigned long)y * f->width + x]);
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
