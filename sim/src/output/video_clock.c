/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* video.mp4's own clock (output_parts.h): frames every speed / fps
 * simulated seconds, whatever trajectories.csv's sample period, each
 * showing the world at its own time, with trails through the world at
 * points at most VIDEO_POINT_S apart (a frame's time among them), as far
 * back as VIDEO_TRAIL_S. */
#include <math.h>

#include "output/output_parts.h"

/* Trails bend where the robots did, to this: a Kilobot walks 1 mm in it,
 * an e-puck at full speed 13. */
#define VIDEO_POINT_S 0.1

void video_clock_init(video_clock *c, const world_spec *w, double fps, double speed)
{
    history_init(&c->points, w, 0);
    const double frame_s = speed / fps;
    c->points_per_frame = (int)ceil(frame_s / VIDEO_POINT_S - 1e-9);
    if (c->points_per_frame < 1)
        c->points_per_frame = 1;
    c->point_s = frame_s / c->points_per_frame;
    c->next = 0;
}

double video_clock_next_s(const video_clock *c)
{
    return (double)c->next * c->point_s;
}

/* The first point not due by t (a world at t stands for every point due). */
static long first_point_after(const video_clock *c, double t)
{
    long next = c->next;
    while ((double)next * c->point_s <= t + 1e-9)
        next++;
    return next;
}

double video_clock_after_s(const video_clock *c, double t)
{
    return (double)first_point_after(c, t) * c->point_s;
}

/* Several points may be due at once when they are closer than the
 * simulator's steps: one world stands for them all. */
int video_clock_add(video_clock *c, const output_sample *s)
{
    int frames = 0;
    output_sample point = *s;
    point.links = NULL; /* a frame draws no IR links */
    point.n_links = 0;
    for (long due = first_point_after(c, s->time_s); c->next < due; c->next++)
        if (c->next % c->points_per_frame == 0)
            frames++;
    if (history_add(&c->points, &point))
        return -1;
    history_forget_before(&c->points, s->time_s - VIDEO_TRAIL_S - c->point_s);
    return frames;
}

void video_clock_free(video_clock *c)
{
    history_free(&c->points);
}
