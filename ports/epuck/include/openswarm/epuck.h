/* The e-puck's devices, as HAL devices with events and processors: the
 * same names on the e-puck2 (STM32F407) and the original e-puck
 * (dsPIC30F6014A), so one app builds for both. Each board supplies the
 * lower layer (ports/epuck/src/epuck_board.h); facts and sources are in
 * ports/epuck/README.md.
 *
 *   device           event                    value
 *   epuck_wheels     EPUCK_EVENT_WHEELS       epuck_wheel_speeds: steps/s, command
 *   epuck_ring_leds  EPUCK_EVENT_RING_LEDS    uint8_t: bit i lights LED i (0 front, clockwise)
 *   epuck_body_led   EPUCK_EVENT_BODY_LED     uint8_t: 0 off, else on (green)
 *   epuck_front_led  EPUCK_EVENT_FRONT_LED    uint8_t: 0 off, else on (red)
 *   epuck_rgb_leds   EPUCK_EVENT_RGB_LEDS     uint8_t: EPUCK_RGB(r, g, b), 0..3 each
 *   epuck_proximity  EPUCK_EVENT_PROXIMITY    epuck_proximity_reading, 100 a second
 *   epuck_camera     EPUCK_EVENT_CAMERA       uint8_t: epuck_seen, from each frame
 *   epuck_selector   EPUCK_EVENT_SELECTOR     uint8_t: 0..15, when it is turned
 */
#ifndef OPENSWARM_EPUCK_H
#define OPENSWARM_EPUCK_H

#include <stdbool.h>

#include "openswarm/event.h"
#include "openswarm/hal.h"
#include "openswarm/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- events (the port's reserved ids) ---- */
#define EPUCK_EVENT_WHEELS ((sys_event_id)(SYS_EVENT_PORT_FIRST + 0))
#define EPUCK_EVENT_RING_LEDS ((sys_event_id)(SYS_EVENT_PORT_FIRST + 1))
#define EPUCK_EVENT_BODY_LED ((sys_event_id)(SYS_EVENT_PORT_FIRST + 2))
#define EPUCK_EVENT_FRONT_LED ((sys_event_id)(SYS_EVENT_PORT_FIRST + 3))
#define EPUCK_EVENT_RGB_LEDS ((sys_event_id)(SYS_EVENT_PORT_FIRST + 4))
#define EPUCK_EVENT_PROXIMITY ((sys_event_id)(SYS_EVENT_PORT_FIRST + 5))
#define EPUCK_EVENT_CAMERA ((sys_event_id)(SYS_EVENT_PORT_FIRST + 6))
#define EPUCK_EVENT_SELECTOR ((sys_event_id)(SYS_EVENT_PORT_FIRST + 7))
#define EPUCK_EVENT_COUNT 8 /* of the port's PORT_EVENT_COUNT */

/* ---- wheels ---- */
#define EPUCK_STEPS_PER_TURN 1000
#define EPUCK_WHEEL_DIAMETER_MM 41
#define EPUCK_AXLE_MM 53
#define EPUCK_MAX_STEPS_PER_S 1000 /* about 129 mm/s */

typedef struct epuck_wheel_speeds {
    int16_t left, right; /* steps per second, + forward */
} epuck_wheel_speeds;

/* The wheels' post-processor (the default): speeds clamped to max_speed,
 * and changed by at most max_step per command, so a controller that
 * reverses at once does not make the steppers lose steps. */
typedef struct epuck_wheel_limits {
    int16_t max_speed; /* steps/s, at most EPUCK_MAX_STEPS_PER_S */
    int16_t max_step;  /* steps/s a command may change a wheel by */
} epuck_wheel_limits;
uint8_t epuck_wheels_limited(sys_device *dev, const void *in, uint8_t size, void *out,
                             uint8_t capacity);
extern epuck_wheel_limits epuck_wheel_default_limits; /* max_speed 1000, max_step 200 */

/* ---- LEDs ---- */
#define EPUCK_RGB(r, g, b) ((uint8_t)(((r)&3) | (((g)&3) << 2) | (((b)&3) << 4)))

/* ---- proximity ---- */
#define EPUCK_PROXIMITY_SENSORS 8

/* One sampling of the eight sensors: ambient is the reading with the IR
 * emitters off, reflected what the pulse added (ambient minus the reading
 * with the pulse on: the receiver's output falls as light rises), both
 * ADC counts, 12 bits; larger reflected, closer obstacle. Sensor 0 is at
 * about +18 deg (front right), then clockwise. */
typedef struct epuck_proximity_reading {
    uint16_t ambient[EPUCK_PROXIMITY_SENSORS];
    uint16_t reflected[EPUCK_PROXIMITY_SENSORS];
} epuck_proximity_reading;

/* The two ADC readings of one sensor, as a board's lower layer takes them:
 * with the emitters off, and at the end of their pulse. */
typedef struct epuck_proximity_samples {
    uint16_t off[EPUCK_PROXIMITY_SENSORS];
    uint16_t pulsed[EPUCK_PROXIMITY_SENSORS];
} epuck_proximity_samples;

/* The proximity pre-processor (the default): samples to a reading. */
uint8_t epuck_proximity_reflection(sys_device *dev, const void *in, uint8_t size, void *out,
                                   uint8_t capacity);

/* ---- camera ---- */
/* Frames are RGB565, row after row; a board delivers a pointer to one
 * (epuck_camera_frame), never the pixels through the event queue. */
typedef struct epuck_camera_frame {
    const uint16_t *pixels;
    uint16_t width, height;
    /* The side, in this frame's pixels, of the classifier's window (the
     * sensor's central 160 x 160). 0: the frame is the whole 640-wide view
     * (the e-puck2's, the world's), the window a quarter of its width; the
     * dsPIC e-puck's 20 x 20 frame is the window itself (20). */
    uint16_t window;
} epuck_camera_frame;

typedef enum epuck_seen { EPUCK_SEEN_NOTHING = 0, EPUCK_SEEN_ROBOT, EPUCK_SEEN_OBJECT } epuck_seen;

/* The camera's pre-processor (the default), the paper's virtual sensor: the
 * central 160 x 160 pixels (of a 640 x 480 frame; a smaller frame's centre,
 * scaled) looked at on a 20 x 20 grid, the original's 24 points (columns 6,
 * 9, 12, 15 by rows 4, 6, ..., 14) each matched to dark, green, red or white
 * (epuck_colour_nearest); 2 or more red or dark: an object; else 2 or more
 * green: a robot; else nothing. Built with EPUCK_CLASSIFIER_BAND: this
 * project's earlier band (columns 2..17, rows 8..11, epuck_colour_of). */
uint8_t epuck_camera_classifier(sys_device *dev, const void *in, uint8_t size, void *out,
                                uint8_t capacity);
/* The same judgement on its own, for code without the kernel (a plain
 * loop): false if the frame is too small to judge (under 20 pixels wide, or
 * shorter than a quarter of its width). */
bool epuck_classify_frame(const epuck_camera_frame *frame, epuck_seen *seen);
/* The colour class of one RGB565 pixel by fixed thresholds (the band
 * classifier's). */
typedef enum epuck_colour {
    EPUCK_COLOUR_OTHER = 0,
    EPUCK_COLOUR_DARK,
    EPUCK_COLOUR_GREEN,
    EPUCK_COLOUR_RED,
    EPUCK_COLOUR_WHITE
} epuck_colour;
epuck_colour epuck_colour_of(uint16_t rgb565);
/* The original classifier's match (OpenSwarm's camera_processing.c): the
 * nearest of dark, green, red and white; never EPUCK_COLOUR_OTHER. */
epuck_colour epuck_colour_nearest(uint16_t rgb565);

/* ---- the devices ---- */
extern sys_device epuck_wheels, epuck_ring_leds, epuck_body_led, epuck_front_led, epuck_rgb_leds,
    epuck_proximity, epuck_camera, epuck_selector;

/* Register every device (after Sys_Init_Kernel) and start the board's
 * sampling (proximity, camera, selector). The first error is returned. */
sys_status epuck_devices_init(void);

#ifdef __cplusplus
}
#endif

#endif
