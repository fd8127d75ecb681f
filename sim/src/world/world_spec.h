/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* A world as world.json declares it, once checked: the arena, what stands
 * and lies in it, its lights, and every robot with its pose, firmware, id
 * and calibration. world_file.cpp reads and checks it; the physics
 * (world.cpp) and the outputs (output/) read it. Lengths are millimetres,
 * angles degrees counter-clockwise from the x axis; the arena spans
 * (0, 0) to (width_mm, height_mm), y up. */
#ifndef OPENSWARM_WORLD_SPEC_H
#define OPENSWARM_WORLD_SPEC_H

#include <stdint.h>

#include "air/ir_distance_error.h"

#define WORLD_MAX_VERTICES 32
/* What one world may hold (docs/world.md, "Limits"). Obstacles are edges
 * of one fixed body: Box2D pairs every two that overlap when the world
 * starts (memory and time growing with the square of a stack of them), so
 * their edges are bounded in all: 4000 of them all overlapping cost about
 * 60 MB and half a second, once. */
#define WORLD_MAX_OBSTACLES 1000
#define WORLD_MAX_OBSTACLE_VERTICES 4000
#define WORLD_MAX_OBJECTS 10000
#define WORLD_MAX_ROBOTS 10000 /* = openswarm-sim's --robots limit */
#define KILOBOT_RADIUS_MM 16.5 /* a Kilobot is a disc 33 mm across */
/* The e-puck's camera and wheels by default (docs/world.md, "e-pucks in the world"). */
#define WORLD_CAMERA_PERIOD_MS 250   /* 4 frames a second */
#define WORLD_CAMERA_MAX_LAG_MS 1000
#define WORLD_CAMERA_FOV_DEG 56.0     /* horizontal field of view */
#define WORLD_CAMERA_RANGE_MM 1500.0  /* a robot or an object farther shows as the wall behind */
#define WORLD_CAMERA_MAX_PIXEL_NOISE 31.0    /* sd in 5-bit counts: a whole channel's range */
#define WORLD_CAMERA_MAX_MISREAD_PCT_PER_M 100.0
/* Each e-puck wheel's speed is its command times a factor drawn anew every
 * step, uniform in 1 +- this %: Enki's e-puck model (DifferentialWheeled's
 * noiseAmount 0.05, EPuck.cpp), slip and all (docs/world.md). */
#define WORLD_WHEEL_NOISE_PCT 5.0
/* An e-puck is 74 mm across (docs/world.md gives the sources). */
#define EPUCK_RADIUS_MM 37.0

/* Which robots a world holds: one kind for all of them. */
enum { WORLD_ROBOT_KILOBOT = 0, WORLD_ROBOT_EPUCK = 1 };
/* How they run: their firmware in simavr (exact), or their app built for
 * the host (native: docs/world.md, "Native mode"). */
/* qemu: an e-puck world's controllers are e-puck2 images, each run by
 * QEMU (epuck_link.c). */
enum { WORLD_FIDELITY_EXACT = 0, WORLD_FIDELITY_NATIVE = 1, WORLD_FIDELITY_QEMU = 2 };

typedef struct world_point {
    double x, y;
} world_point;

/* A fixed obstacle: a simple polygon (rectangles become four corners),
 * vertices in order, either way round. */
typedef struct world_obstacle {
    int n;
    world_point v[WORLD_MAX_VERTICES];
} world_obstacle;

/* A movable round object that robots push. */
typedef struct world_object {
    world_point at;
    double radius_mm;
    double mass_g;
    double friction; /* ground friction coefficient, 0..2 */
} world_object;

/* A light source: it adds intensity_mv to a light sensor 100 mm away,
 * falling with the square of the distance beyond that; its bulb stands
 * height_mm above the floor (kilobot_light.h). */
typedef struct world_light {
    world_point at;
    double intensity_mv;
    double height_mm;
} world_light;

typedef struct world_robot {
    world_point at;
    double heading_deg;
    int uid;            /* 0..65535 */
    int firmware;       /* index into world_spec.firmware; -1: the command line's */
    int group;          /* its group's index in robots[], for messages */
    int calibration[4]; /* EEPROM: turn left, turn right, straight left, straight right;
                           -2: the robot's own (factory) duties; -1: erased */
} world_robot;

/* A Kilobot's EEPROM, and where the app's part starts: kilolib keeps its
 * calibration, distance tables, IR mask and uid below 0x100. */
#define WORLD_EEPROM_BYTES 1024
#define WORLD_EEPROM_APP_START 0x100

typedef struct world_spec {
    const char *path; /* the file, for messages */
    double width_mm, height_mm;
    world_obstacle *obstacles;
    int n_obstacles;
    world_object *objects;
    int n_objects;
    world_light *lights;
    int n_lights;
    double ambient_light_mv; /* the light sensor's input with no source near */
    int light_unshaded;      /* "light": {"shadow": false}: no battery shadow on the sensor */
    int wheel_noise_off;     /* "noise": {"wheels": false}: e-puck wheels turn exactly as commanded */
    double wheel_noise_pct;  /* "noise": {"wheels_pct": P}: each wheel errs by +- P %; 0: the default */
    int camera_period_ms;    /* "camera": {"frames_per_s": F}: 1000 / F; 0: the default */
    int camera_lag_ms;       /* "camera": {"lag_ms": L}: a frame reaches the controller L ms after it is taken */
    double camera_fov_deg;   /* "camera": {"fov_deg": D}; 0: the default */
    double camera_range_mm;  /* "camera": {"range_mm": R}; 0: the default */
    double camera_pixel_noise;       /* "camera": {"pixel_noise": S}: each channel's sd, 5-bit counts; 0: none */
    double camera_misread_pct_per_m; /* "camera": {"misread_pct_per_m": P}: a far body's column shows the wall; 0: none */
    world_robot *robots;
    int n_robots;
    char **firmware; /* ELF paths named in the file, relative to the file resolved */
    int n_firmware;
    int ir_range_mm;         /* -1: not given (the simulator's default) */
    double ir_loss_pct;      /* -1: not given */
    double ir_distance_bias_mm;  /* each pair's estimates off by up to this; given or the default */
    double ir_distance_noise_mm; /* each message's own error's sd; given or the default */
    double clock_spread_pct; /* -1: not given */
    uint32_t seed;           /* motion noise, motor variation, analog noise, placement, IR distance error */
    double duration_s;       /* -1: not given (--time or its default) */
    double sample_period_s;  /* trajectories.csv's period; default 0.1 */
    int robot_kind;          /* WORLD_ROBOT_*: "robot" in the file, kilobot by default */
    int fidelity;            /* WORLD_FIDELITY_*: "fidelity" in the file, exact by default */
    double robot_radius_mm;  /* its body's */
    /* "eeprom": bytes every robot's EEPROM holds before it starts (the
     * app's values, "at": "eeprom"), where eeprom_given is set. */
    uint8_t eeprom[WORLD_EEPROM_BYTES];
    uint8_t eeprom_given[WORLD_EEPROM_BYTES];
} world_spec;

#ifdef __cplusplus
extern "C" {
#endif

/* Read and check path; on any mistake print "path:line:column: what is
 * wrong; what to do" on stderr and return -1 (nothing else is touched). */
int world_spec_load(const char *path, world_spec *out);
static inline int world_camera_period_ms(const world_spec *w) {
    return w->camera_period_ms > 0 ? w->camera_period_ms : WORLD_CAMERA_PERIOD_MS;
}
static inline double world_camera_fov_deg(const world_spec *w) {
    return w->camera_fov_deg > 0 ? w->camera_fov_deg : WORLD_CAMERA_FOV_DEG;
}
static inline double world_camera_range_mm(const world_spec *w) {
    return w->camera_range_mm > 0 ? w->camera_range_mm : WORLD_CAMERA_RANGE_MM;
}
/* Each e-puck wheel's speed error, +- this fraction of the command; 0: none. */
static inline double world_wheel_noise(const world_spec *w) {
    if (w->wheel_noise_off) return 0;
    return (w->wheel_noise_pct > 0 ? w->wheel_noise_pct : WORLD_WHEEL_NOISE_PCT) / 100.0;
}
/* The radius of w's robots (a Kilobot's if w does not say). */
static inline double world_robot_radius(const world_spec *w) {
    return w->robot_radius_mm > 0 ? w->robot_radius_mm : KILOBOT_RADIUS_MM;
}
void world_spec_free(world_spec *w);

#ifdef __cplusplus
}
#endif

#endif
