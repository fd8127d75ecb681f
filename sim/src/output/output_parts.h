/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The parts output.c puts together, one file each: the run kept so far
 * (history.c), the CSV files (trajectories.c), one frame drawn with Cairo
 * (picture.c, the strip below it picture_footer.c), the ffmpeg pipe (video.c) and the browser player
 * (viewer.c). Each reports its own errors on stderr, naming the path. */
#ifndef OPENSWARM_OUTPUT_PARTS_H
#define OPENSWARM_OUTPUT_PARTS_H

#include <stdio.h>
#include <sys/types.h>

#include <cairo.h>

#include "output/output.h"

/* ---- part_file.c: each file is written as NAME.part and renamed to NAME
 * when whole, so a killed run never leaves half a file under its name. */
char *part_file_name(const char *path); /* malloc'd "path.part", NULL out of memory */
/* complete: rename path.part to path; otherwise remove path.part. -1
 * after a message, or when not complete. */
int part_file_finish(const char *path, int complete);
/* A CSV file written row by row as path.part, its header line first;
 * NULL after a message naming the path. */
FILE *part_table_open(const char *path, const char *header);
/* Closed; keep: renamed into place (else removed). -1 after a message
 * when it could not be written whole. A NULL f is nothing to close. */
int part_table_close(FILE *f, const char *path, int keep);

/* ---- history.c: the run so far, copied sample by sample for final.png's
 * trails and viewer.html. It is bounded: past its budget (by default
 * HISTORY_BUDGET_BYTES) it keeps every other sample it holds (and each
 * later one on the new stride), so a thousand robots for ten minutes stay
 * in memory and the viewer stays loadable; the newest sample is always
 * there. 100 robots x 6000 samples (10 minutes at 0.1 s) fit whole. */
#define HISTORY_BUDGET_BYTES (64u << 20)
typedef struct output_history {
    const world_spec *world;
    size_t budget;          /* bytes */
    int n, capacity;        /* samples kept */
    int stride;             /* kept: every stride-th sample added, and the newest */
    long added;             /* samples added so far */
    long *number;           /* [n]: each kept sample's number among those added */
    double *time_s;         /* [n] */
    output_robot *robots;   /* [n * world->n_robots] */
    world_point *objects;   /* [n * world->n_objects] */
    int *link_start;        /* [n + 1]: sample k's links are links[link_start[k] ..] */
    output_link *links;
    int n_links, links_capacity;
} output_history;

void history_init(output_history *h, const world_spec *w, size_t budget); /* 0: the default */
int history_add(output_history *h, const output_sample *s); /* -1: out of memory */
/* Drops the samples before t (never the newest), a video's trails being
 * only so long; in bulk, once they are half of those held. */
void history_forget_before(output_history *h, double t);
void history_free(output_history *h);
static inline const output_robot *history_robots(const output_history *h, int k)
{
    return h->robots + (size_t)k * (size_t)h->world->n_robots;
}
static inline const world_point *history_objects(const output_history *h, int k)
{
    return h->objects + (size_t)k * (size_t)h->world->n_objects;
}

/* ---- trajectories.c: trajectories.csv and objects.csv, row by row. */
typedef struct output_tables {
    FILE *robots, *objects;
    char *robots_path, *objects_path;
} output_tables;

int tables_open(output_tables *t, const char *robots_path, const char *objects_path);
int tables_add(output_tables *t, const world_spec *w, const output_sample *s);
/* keep: rename the .part files into place (else they are removed). */
int tables_close(output_tables *t, int keep);

/* ---- ir_table.c: ir.csv, each Kilobot's IR counters at every sample. */
typedef struct ir_table {
    FILE *file;
    char *path;
} ir_table;

int ir_table_open(ir_table *t, const char *path);
/* s->ir's n_robots rows; a sample without them (NULL) writes none. */
int ir_table_add(ir_table *t, int n_robots, const output_sample *s);
int ir_table_close(ir_table *t, int keep);

/* ---- picture.c: a top view of the world at one sample. The image fits
 * the arena in about 800 pixels on its long side; its width and height are
 * even (what yuv420p video needs). */
typedef struct picture {
    cairo_surface_t *surface;
    cairo_t *cr;
    cairo_surface_t *background; /* what never moves, drawn at the first frame */
    int width, height;
    double scale;              /* pixels per mm */
    double origin_x, origin_y; /* pixel of the arena's (0, 0) corner */
    double robot_radius_mm;
    double trail_s; /* how far back the trails reach; 0: 15 s (a video's frames) */
    int starts;     /* mark where each robot started (final.png) */
    int ids;        /* write each robot's number beside it (--ids) */
} picture;

int picture_init(picture *p, const world_spec *w);
/* Sample k of h (with the trails leading to it); k < 0: the world as
 * world.json sets it up, before any sample. */
void picture_draw(picture *p, const output_history *h, int k);
void picture_to_pixel(const picture *p, double x_mm, double y_mm, double *px, double *py);
/* picture_footer.c: the strip below the arena at time_s, with the legend
 * of the robots' LEDs (robots NULL: before any sample). */
void picture_draw_footer(picture *p, const world_spec *w, double time_s, const output_robot *robots);
int picture_write_png(picture *p, const char *path);
void picture_free(picture *p);
/* A Kilobot LED channel (0..3) as an 8-bit intensity: 255 x the square
 * root of level / 3. Brightness as the eye sees it grows about as the
 * square root of the light (Stevens' power law), so the dimmest level,
 * which the classic labs use for their dim white, reads as lit (147, a
 * light grey) and not as a third of full (85, darker than an unlit
 * robot's body was drawn). The viewer (viewer_page.html's ledColour)
 * draws the same. */
static inline int led_level_8bit(int level)
{
    static const int drawn[4] = {0, 147, 208, 255};
    return drawn[level < 0 ? 0 : level > 3 ? 3 : level];
}

/* ---- video.c: frames piped to ffmpeg, no files in between. */
typedef struct video {
    FILE *pipe;
    pid_t ffmpeg;
    char *path;
    int width, height;
    long frames;
    int failed;
} video;

/* fps frames a second of the file; fails (with the fix) when ffmpeg is
 * not on the PATH. */
int video_open(video *v, const char *path, int width, int height, double fps);
/* ffmpeg is on the PATH; -1 after a message naming the fix if not. */
int video_check(void);
int video_frame(video *v, cairo_surface_t *frame);
int video_close(video *v); /* ffmpeg's exit status checked */

/* ---- video_clock.c: the video's own clock, apart from the samples: a
 * frame every speed / fps simulated seconds, and the world at points
 * between them for the trails, the last VIDEO_TRAIL_S of them kept. */
#define VIDEO_TRAIL_S 15.0
typedef struct video_clock {
    output_history points; /* the world at each point so far, links left out */
    double point_s;        /* simulated seconds between points */
    int points_per_frame;
    long next;             /* the next point's number: due at next x point_s */
} video_clock;

void video_clock_init(video_clock *c, const world_spec *w, double fps, double speed);
double video_clock_next_s(const video_clock *c);
/* When it wants the world next once it has the world at t. */
double video_clock_after_s(const video_clock *c, double t);
/* The world at s->time_s for every point due by then; how many of those
 * are frames (each to be drawn from the newest point), -1 out of memory. */
int video_clock_add(video_clock *c, const output_sample *s);
void video_clock_free(video_clock *c);

/* ---- viewer.c: viewer.html, the run and its player in one file. */
int viewer_write(const char *path, const output_history *h);

#endif
