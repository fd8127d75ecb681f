/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* What a run in a world leaves in --out DIR: trajectories.csv, objects.csv,
 * ir.csv (Kilobot worlds), final.png (a top view at the end), viewer.html (the run played back in a
 * browser, one file, no network) and, when asked, video.mp4 (Cairo frames
 * piped to ffmpeg). The simulator hands over one sample per sample period,
 * and the video's frames at the video's own rate. */
#ifndef OPENSWARM_OUTPUT_H
#define OPENSWARM_OUTPUT_H

#include <stddef.h>
#include <stdint.h>

#include "world/world_spec.h"

/* A robot at one sample: where it is and what its LED shows (each channel
 * 0..3, as the Kilobot's 2-bit colour). */
typedef struct output_robot {
    double x_mm, y_mm, heading_deg;
    uint8_t led_r, led_g, led_b;
} output_robot;

/* An IR link: receiver hears sender (they are within IR range). */
typedef struct output_link {
    int sender, receiver;
} output_link;

/* A Kilobot's IR at one sample (a row of ir.csv), counted from the run's
 * start: its firmware's own counters (kilobot_ir_stats, in its order:
 * sent, received, refused, bad_crc, broken, collisions, busy; unknown for
 * a firmware that keeps none) and the channel's, for it as a receiver:
 * frames from robots in range that reached it, and those the channel lost
 * on the way (ir.loss_pct's draw; natively also a full inbox). */
#define OUTPUT_IR_FIRMWARE_COUNTERS 7
typedef struct output_ir {
    int firmware_known;
    uint16_t firmware[OUTPUT_IR_FIRMWARE_COUNTERS];
    uint64_t heard, lost_channel;
} output_ir;

typedef struct output_sample {
    double time_s;
    const output_robot *robots; /* world_spec.n_robots of them */
    const world_point *objects; /* world_spec.n_objects centres */
    const output_link *links;
    int n_links;
    const output_ir *ir; /* one a robot; NULL: no IR (e-pucks, a video frame) */
} output_sample;

typedef struct output_options {
    const char *dir;      /* created if missing */
    int video;            /* also write video.mp4 (needs ffmpeg on the PATH) */
    int quiet;            /* no list of written files at the end */
    int ids;              /* final.png and the video number the robots (--ids) */
    double video_fps;     /* the video's frames a second; 0: 25 */
    double video_speed;   /* simulated seconds a second of video; 0: 1 (real time) */
    size_t history_bytes; /* the samples kept for final.png and viewer.html; 0: 64 MB */
} output_options;

/* At most this many rows of trajectories.csv and objects.csv together
 * (robots and objects x samples): about 2 GB of CSV (docs/world.md; the
 * history kept for viewer.html is bounded apart, history_bytes). */
#define OUTPUT_MAX_ROWS 50000000.0

/* What can be checked before anything is opened (--video needs ffmpeg on
 * the PATH); -1 after a message naming the fix. */
int output_check(const output_options *o);
/* Open the outputs; -1 with a message naming the path and the fix. The
 * world is kept by reference until output_close. */
int output_open(const output_options *o, const world_spec *w);
/* One sample, in time order. -1 on a write error (reported). */
int output_sample_add(const output_sample *s);
/* With a video: when it next wants the world (its frames every
 * video_speed / video_fps simulated seconds, from 0, and points between
 * them for the trails); INFINITY without. The caller hands it over with
 * output_frame_add at that time or the first step after it, apart from
 * the samples; -1 on a write error (reported). */
double output_next_frame_s(void);
/* When it will want the world next once handed the world at t: for a
 * caller that notes what a frame shows before it hands it over. */
double output_frame_after_s(double t);
int output_frame_add(const output_sample *s);
/* Write what is written at the end (final.png, viewer.html), finish the
 * video, close the files; -1 if any of it failed (reported). Each file is
 * written as NAME.part and renamed to NAME once whole (part_file.c):
 * trajectories.csv and objects.csv are .part files while the run goes. */
int output_close(void);
/* The files the last output_close wrote, ", " between them ("" none). */
const char *output_written(void);
/* output_close names no files: the caller says what it wrote its way
 * (an interrupted run, interrupt.h). */
void output_quieten(void);

#endif
