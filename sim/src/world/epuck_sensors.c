/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
#include "world/epuck_sensors.h"

#include <math.h>

#include "world/world_random.h"

/* Where each sensor looks, counter-clockwise from the heading: sensor 0
 * front right, then clockwise round the body (epuck.h's numbering). */
static const double SENSOR_DEG[EPUCK_SENSOR_COUNT] = {-18, -45, -90, -142, 142, 90, 45, 18};
/* The proximity model (docs/world.md): reflected counts fall off
 * exponentially from about CONTACT counts with the body's distance; the
 * receiver rests at AMBIENT with the emitters off; each sample carries
 * gaussian noise. Beyond RANGE_MM nothing is reflected at all. */
#define CONTACT_COUNTS 3700.0
#define FALL_MM 9.6
#define AMBIENT_COUNTS 3800.0
#define NOISE_COUNTS 8.0
#define RANGE_MM 120.0
#define ADC_MAX 4095.0
/* The camera's horizontal field of view, degrees, and how far it tells a
 * robot or an object from the white walls behind (docs/world.md). */
#define CAMERA_FOV_DEG 56.0
#define CAMERA_RANGE_MM 1500.0
#define GREEN565 0x07E0u
#define RED565 0xF800u
#define WHITE565 0xFFFFu

double epuck_reflection_counts(double distance_mm) {
    if (distance_mm >= RANGE_MM) return 0.0;
    if (distance_mm < 0) distance_mm = 0;
    return CONTACT_COUNTS * exp(-distance_mm / FALL_MM);
}

static uint16_t adc(double counts) {
    if (counts < 0) return 0;
    if (counts > ADC_MAX) return (uint16_t)ADC_MAX;
    return (uint16_t)lround(counts);
}

void epuck_proximity_read(const world *w, int robot, uint16_t off[EPUCK_SENSOR_COUNT],
                          uint16_t pulsed[EPUCK_SENSOR_COUNT], uint64_t *rng) {
    double x, y, heading;
    world_robot_pose(w, robot, &x, &y, &heading);
    double radius = world_robot_radius(world_spec_of(w));
    for (int k = 0; k < EPUCK_SENSOR_COUNT; k++) {
        world_hit hit = world_ray(w, robot, x, y, heading + SENSOR_DEG[k], radius + RANGE_MM);
        double reflected = hit.kind == WORLD_HIT_NONE ? 0.0 : epuck_reflection_counts(hit.distance_mm - radius);
        double resting = AMBIENT_COUNTS + NOISE_COUNTS * world_random_normal(rng);
        off[k] = adc(resting);
        pulsed[k] = adc(resting - reflected + NOISE_COUNTS * world_random_normal(rng));
    }
}

static uint16_t colour_of(world_hit hit) {
    /* Farther, a robot or an object is too small in the frame to tell:
     * the walls behind it show. */
    if (hit.kind != WORLD_HIT_WALL && hit.distance_mm > CAMERA_RANGE_MM) return WHITE565;
    switch (hit.kind) {
    case WORLD_HIT_ROBOT: return GREEN565;
    case WORLD_HIT_OBJECT: return RED565;
    case WORLD_HIT_WALL: return WHITE565;
    default: return 0; /* nothing: dark */
    }
}

void epuck_camera_render(const world *w, int robot,
                         uint16_t pixels[EPUCK_FRAME_WIDTH * EPUCK_FRAME_HEIGHT]) {
    double x, y, heading;
    world_robot_pose(w, robot, &x, &y, &heading);
    const world_spec *s = world_spec_of(w);
    double reach = hypot(s->width_mm, s->height_mm);
    for (int col = 0; col < EPUCK_FRAME_WIDTH; col++) {
        /* Column 0 is the image's left: counter-clockwise of the heading. */
        double offset = CAMERA_FOV_DEG * (0.5 - (col + 0.5) / EPUCK_FRAME_WIDTH);
        uint16_t c = colour_of(world_ray(w, robot, x, y, heading + offset, reach));
        for (int row = 0; row < EPUCK_FRAME_HEIGHT; row++) pixels[row * EPUCK_FRAME_WIDTH + col] = c;
    }
}
