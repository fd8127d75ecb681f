/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* Drives sim/src/output alone, as the simulator will: a 400 x 300 mm arena
 * with an obstacle, an object, a light and three robots moving on known
 * paths with known LEDs, 50 samples 0.1 s apart (t = 0.0 .. 4.9 s), and
 * with --video the video's frames, 25 a second (t = 0.0 .. 4.96 s).
 *   robot 0: (50 + 20 t, 50), heading 0, LED red 3
 *   robot 1: on a circle of 60 mm about (200, 150), 36 degrees a second
 *            from the x axis, heading along it; LED green 2, green 3 from 2.5 s
 *   robot 2: still at (320, 120), heading -90; LED off, (1, 2, 3) from 2.0 s
 *   object 0: (100 + 2 t, 220), radius 20
 * IR links join robots within 100 mm, both ways. --dim: robot 0's LED is
 * the classic labs' dim white (1, 1, 1) and robot 2's stays off.
 * usage: output_driver OUT_DIR [--video] [--quiet] [--ids] [--dim] [--history-bytes N] */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "output/output.h"

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: output_driver OUT_DIR [--video] [--quiet] [--ids] [--dim] [--history-bytes N]\n");
        return 2;
    }
    output_options o = {.dir = argv[1]};
    int dim = 0;
    for (int i = 2; i < argc; i++) {
        if (!strcmp(argv[i], "--video"))
            o.video = 1;
        else if (!strcmp(argv[i], "--quiet"))
            o.quiet = 1;
        else if (!strcmp(argv[i], "--ids"))
            o.ids = 1;
        else if (!strcmp(argv[i], "--dim"))
            dim = 1;
        else if (!strcmp(argv[i], "--history-bytes") && i + 1 < argc)
            o.history_bytes = strtoul(argv[++i], NULL, 10);
    }

    world_obstacle wall = {.n = 4, .v = {{260, 200}, {340, 200}, {340, 260}, {260, 260}}};
    world_object ball = {.at = {100, 220}, .radius_mm = 20, .mass_g = 10, .friction = 0.5};
    world_light lamp = {.at = {360, 40}, .intensity_mv = 400};
    world_robot robots[3] = {
        {.at = {50, 50}, .heading_deg = 0, .uid = 1, .firmware = -1},
        {.at = {260, 150}, .heading_deg = 90, .uid = 2, .firmware = -1},
        {.at = {320, 120}, .heading_deg = -90, .uid = 3, .firmware = -1},
    };
    world_spec w = {.path = "output_driver", .width_mm = 400, .height_mm = 300,
                    .obstacles = &wall, .n_obstacles = 1, .objects = &ball, .n_objects = 1,
                    .lights = &lamp, .n_lights = 1, .robots = robots, .n_robots = 3,
                    .ir_range_mm = 100, .ir_loss_pct = -1, .clock_spread_pct = -1,
                    .duration_s = 5, .sample_period_s = 0.1};
    if (output_open(&o, &w))
        return 1;

    /* The world every 20 ms, as the simulator's steps: a sample every 0.1 s,
     * the video's frames (--video) when it asks for them. */
    for (int step = 0; step < 250; step++) {
        const int k = step / 5; /* the sample it belongs to */
        const double t = step / 50.0, a = 36 * t * M_PI / 180;
        output_robot r[3] = {
            {.x_mm = 50 + 20 * t, .y_mm = 50, .heading_deg = 0, .led_r = dim ? 1 : 3, .led_g = dim,
             .led_b = dim},
            {.x_mm = 200 + 60 * cos(a), .y_mm = 150 + 60 * sin(a), .heading_deg = 36 * t + 90,
             .led_g = k >= 25 ? 3 : 2},
            {.x_mm = 320, .y_mm = 120, .heading_deg = -90, .led_r = k >= 20 && !dim ? 1 : 0,
             .led_g = k >= 20 && !dim ? 2 : 0, .led_b = k >= 20 && !dim ? 3 : 0},
        };
        world_point objects[1] = {{100 + 2 * t, 220}};
        output_link links[6];
        int n_links = 0;
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                if (i != j && hypot(r[i].x_mm - r[j].x_mm, r[i].y_mm - r[j].y_mm) <= 100)
                    links[n_links++] = (output_link){.sender = i, .receiver = j};
        output_sample s = {.time_s = t, .robots = r, .objects = objects, .links = links,
                           .n_links = n_links};
        if ((step % 5 == 0 && output_sample_add(&s)) ||
            (o.video && t + 1e-9 >= output_next_frame_s() && output_frame_add(&s))) {
            output_close();
            return 1;
        }
    }
    return output_close() ? 1 : 0;
}
