/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
#include "world/epuck_sensors.h"

#include <math.h>
#include <stddef.h>

#include "world/epuck_camera_noise.h"
#include "world/world_random.h"

/* Where each sensor looks, counter-clockwise from the heading: sensor 0
 * front right, then clockwise round the body (epuck.h's numbering). */
static const double SENSOR_DEG[EPUCK_SENSOR_COUNT] = {-18, -45, -90, -142, 142, 90, 45, 18};
/* The proximity model (docs/world.md): what one sensor reflects at a
 * distance from its window, from the calibration Cyberbotics made on a
 * real e-puck for Webots' model (E-puckDistanceSensor.proto): mm, counts,
 * and the noise's standard deviation as a share of the counts; between
 * two points the curve is a straight line, as Webots draws it. The last
 * point is what the sensor reads with nothing near it: the e-puck
 * library's e_calibrate_ir() takes that away, so here it is the zero. */
typedef struct {
    double mm, counts, noise_share;
} response_point;
static const response_point RESPONSE[] = {
    {0, 4095, 0.002},    {5, 2133.33, 0.003}, {10, 1465.73, 0.007}, {15, 601.46, 0.0406},
    {20, 383.84, 0.01472}, {30, 234.93, 0.0241}, {40, 158.03, 0.0287}, {50, 120, 0.04225},
    {60, 104.09, 0.03065}, {70, 67.19, 0.04897},
};
#define RESPONSE_POINTS (sizeof RESPONSE / sizeof RESPONSE[0])
#define RANGE_MM 70.0
/* The receiver's level with the emitters off, and how much ambient light
 * moves it from one round to the next (ours: both samples of a round see
 * the same ambient, so it cancels out of the reflection). */
#define AMBIENT_COUNTS 3800.0
#define AMBIENT_NOISE_COUNTS 8.0
#define ADC_MAX 4095.0
#define GREEN565 0x07E0u
#define RED565 0xF800u
#define WHITE565 0xFFFFu

/* The response at distance_mm, and its noise share: RESPONSE's line
 * through the two points either side; past the last point, the last. */
static response_point response_at(double distance_mm) {
    if (distance_mm <= 0) return RESPONSE[0];
    for (size_t i = 1; i < RESPONSE_POINTS; i++) {
        const response_point *a = &RESPONSE[i - 1], *b = &RESPONSE[i];
        if (distance_mm > b->mm) continue;
        double t = (distance_mm - a->mm) / (b->mm - a->mm);
        return (response_point){distance_mm, a->counts + t * (b->counts - a->counts),
                                a->noise_share + t * (b->noise_share - a->noise_share)};
    }
    return RESPONSE[RESPONSE_POINTS - 1];
}

double epuck_reflection_counts(double distance_mm) {
    return response_at(distance_mm).counts - RESPONSE[RESPONSE_POINTS - 1].counts;
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
        double distance = hit.kind == WORLD_HIT_NONE ? RANGE_MM : hit.distance_mm - radius;
        response_point r = response_at(distance);
        double seen = r.counts * (1.0 + r.noise_share * world_random_normal(rng));
        double reflected = seen - RESPONSE[RESPONSE_POINTS - 1].counts;
        double resting = AMBIENT_COUNTS + AMBIENT_NOISE_COUNTS * world_random_normal(rng);
        off[k] = adc(resting);
        pulsed[k] = adc(resting - reflected);
    }
}

static uint16_t colour_of(world_hit hit, double range_mm) {
    /* Farther, a robot or an object is too small in the frame to tell:
     * the walls behind it show. */
    if (hit.kind != WORLD_HIT_WALL && hit.distance_mm > range_mm) return WHITE565;
    switch (hit.kind) {
    case WORLD_HIT_ROBOT: return GREEN565;
    case WORLD_HIT_OBJECT: return RED565;
    case WORLD_HIT_WALL: return WHITE565;
    default: return 0; /* nothing: dark */
    }
}

void epuck_camera_render(const world *w, int robot,
                         uint16_t pixels[EPUCK_FRAME_WIDTH * EPUCK_FRAME_HEIGHT], uint64_t *rng) {
    double x, y, heading;
    world_robot_pose(w, robot, &x, &y, &heading);
    const world_spec *s = world_spec_of(w);
    double reach = hypot(s->width_mm, s->height_mm);
    /* The field of view and the range: docs/world.md, "camera" (the world
     * file may set both). */
    double fov_deg = world_camera_fov_deg(s), range_mm = world_camera_range_mm(s);
    for (int col = 0; col < EPUCK_FRAME_WIDTH; col++) {
        /* Column 0 is the image's left: counter-clockwise of the heading. */
        double offset = fov_deg * (0.5 - (col + 0.5) / EPUCK_FRAME_WIDTH);
        world_hit hit = world_ray(w, robot, x, y, heading + offset, reach);
        uint16_t c = colour_of(hit, range_mm);
        int body = hit.kind == WORLD_HIT_ROBOT || hit.kind == WORLD_HIT_OBJECT;
        if (body && c != WHITE565 && epuck_camera_misread(hit.distance_mm, s->camera_misread_pct_per_m, rng))
            c = WHITE565;
        for (int row = 0; row < EPUCK_FRAME_HEIGHT; row++) pixels[row * EPUCK_FRAME_WIDTH + col] = c;
    }
    epuck_camera_pixel_noise(pixels, EPUCK_FRAME_WIDTH * EPUCK_FRAME_HEIGHT, s->camera_pixel_noise, rng);
}
