/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* A Kilobot's light sensor under lamps (kilobot_light.h). The numbers and
 * their sources are in docs/world.md's light model table. */
#include "world/kilobot_light.h"

#include <math.h>

#define REFERENCE_MM 100.0 /* a source adds its intensity at this distance */
#define NEAREST_MM 10.0    /* closer, the sensor sees the source's own size */
/* Where the phototransistor sits: on the top, 14.5 mm from the body's
 * centre, 100 degrees counter-clockwise from the heading, 34.4 mm above
 * the floor (legs 21.7 + body 12.7). */
#define SENSOR_FROM_CENTRE_MM 14.5
#define SENSOR_BEARING_DEG 100.0
#define SENSOR_HEIGHT_MM 34.4
/* The coin cell on top, centred: what shades the sensor. */
#define BATTERY_RADIUS_MM 10.0
#define BATTERY_ABOVE_SENSOR_MM 4.0
/* The lamp's bulb, whose size softens the shadow's edge. */
#define BULB_RADIUS_MM 30.0

typedef struct { double x, y; } point;

/* The share of a lamp's bulb the sensor at s sees past the battery centred
 * at c: 1 clear, 0 hidden, between in the penumbra. The horizontal ray to
 * the lamp enters the battery's disc (if it does) at x1 mm from the
 * sensor; the bulb is hidden while its centre's elevation is below the
 * battery's top edge seen from there, by more than the bulb's own angular
 * radius. */
static double unshaded(point s, point c, point lamp, double lamp_rise_mm) {
    double dx = lamp.x - s.x, dy = lamp.y - s.y;
    double across = hypot(dx, dy);
    if (across < 1e-9) return 1.0; /* straight above */
    double ux = dx / across, uy = dy / across;
    double along = (c.x - s.x) * ux + (c.y - s.y) * uy; /* the battery's centre on the ray */
    double off = fabs((c.x - s.x) * uy - (c.y - s.y) * ux);
    if (along <= 0 || off >= BATTERY_RADIUS_MM) return 1.0;
    double x1 = along - sqrt(BATTERY_RADIUS_MM * BATTERY_RADIUS_MM - off * off);
    if (x1 <= 0 || x1 >= across) return 1.0; /* the lamp stands before the battery */
    double clearance = atan2(lamp_rise_mm, across) - atan2(BATTERY_ABOVE_SENSOR_MM, x1);
    double bulb = atan2(BULB_RADIUS_MM, hypot(across, lamp_rise_mm));
    double share = 0.5 + clearance / (2 * bulb);
    return share < 0 ? 0 : share > 1 ? 1 : share;
}

double kilobot_light_mv(const world_spec *spec, double x_mm, double y_mm, double heading_deg) {
    double h = heading_deg * M_PI / 180.0, b = h + SENSOR_BEARING_DEG * M_PI / 180.0;
    point centre = {x_mm, y_mm};
    point sensor = {x_mm + SENSOR_FROM_CENTRE_MM * cos(b), y_mm + SENSOR_FROM_CENTRE_MM * sin(b)};
    double mv = spec->ambient_light_mv;
    for (int k = 0; k < spec->n_lights; k++) {
        const world_light *l = &spec->lights[k];
        point lamp = {l->at.x, l->at.y};
        double rise = l->height_mm - SENSOR_HEIGHT_MM;
        double d = hypot(hypot(lamp.x - sensor.x, lamp.y - sensor.y), rise);
        if (d < NEAREST_MM) d = NEAREST_MM;
        double fall = (REFERENCE_MM / d) * (REFERENCE_MM / d);
        double seen = spec->light_unshaded ? 1.0 : unshaded(sensor, centre, lamp, rise);
        mv += l->intensity_mv * fall * seen;
    }
    return mv;
}
