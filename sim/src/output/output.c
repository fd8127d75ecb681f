/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The outputs of a run in a world (output.h): the folder, and which part
 * writes what when. The CSV files and the video take each sample as it
 * comes; final.png and viewer.html are written at the end, from the run
 * kept in memory. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "output/output_parts.h"

static struct {
    int open;
    output_options options;
    const world_spec *world;
    char *dir;
    output_tables tables;
    ir_table ir; /* Kilobot worlds only: e-pucks have no IR channel */
    output_history history;
    picture picture;
    video video;
    video_clock clock;
    int failed;
} out;

/* What the last output_close wrote, for output_written. */
static char written[4096];

/* dir/name, or NULL when out of memory. */
static char *path_in(const char *dir, const char *name)
{
    size_t n = strlen(dir) + strlen(name) + 2;
    char *p = malloc(n);
    if (p)
        snprintf(p, n, "%s%s%s", dir, dir[0] && dir[strlen(dir) - 1] == '/' ? "" : "/", name);
    return p;
}

/* mkdir -p: each missing folder of the path, in turn. */
static int make_folder(const char *dir)
{
    char *p = strdup(dir);
    if (!p)
        return -1;
    int rc = 0;
    for (char *c = p + 1;; c++) {
        if (*c == '/' || *c == 0) {
            char was = *c;
            *c = 0;
            struct stat st;
            if (mkdir(p, 0777) != 0 && errno != EEXIST) {
                fprintf(stderr, "openswarm-sim: cannot create the output folder %s: %s; choose "
                                "another --out folder or fix its permissions\n",
                        p, strerror(errno));
                rc = -1;
                break;
            }
            if (stat(p, &st) != 0 || !S_ISDIR(st.st_mode)) {
                fprintf(stderr, "openswarm-sim: cannot create the output folder %s: a file of "
                                "that name is in the way; choose another --out folder\n",
                        p);
                rc = -1;
                break;
            }
            *c = was;
            if (!was)
                break;
            while (c[1] == '/')
                c++;
        }
    }
    free(p);
    return rc;
}

static void close_all(void)
{
    tables_close(&out.tables, 0);
    ir_table_close(&out.ir, 0);
    video_close(&out.video);
    video_clock_free(&out.clock);
    picture_free(&out.picture);
    history_free(&out.history);
    free(out.dir);
    memset(&out, 0, sizeof out);
}

int output_check(const output_options *o)
{
    return o->video ? video_check() : 0;
}

int output_open(const output_options *o, const world_spec *w)
{
    if (out.open)
        close_all();
    memset(&out, 0, sizeof out);
    out.options = *o;
    out.world = w;
    const char *dir = o->dir && o->dir[0] ? o->dir : ".";
    out.dir = strdup(dir);
    if (!out.dir || make_folder(dir))
        goto fail;
    char *robots = path_in(dir, "trajectories.csv"), *objects = path_in(dir, "objects.csv");
    int rc = robots && objects ? tables_open(&out.tables, robots, objects) : -1;
    free(robots);
    free(objects);
    if (rc)
        goto fail;
    if (w->robot_kind == WORLD_ROBOT_KILOBOT) {
        char *ir = path_in(dir, "ir.csv");
        rc = ir ? ir_table_open(&out.ir, ir) : -1;
        free(ir);
        if (rc)
            goto fail;
    }
    history_init(&out.history, w, o->history_bytes);
    if (picture_init(&out.picture, w))
        goto fail;
    out.picture.ids = o->ids;
    if (o->video) {
        const double fps = o->video_fps > 0 ? o->video_fps : 25, speed = o->video_speed > 0 ? o->video_speed : 1;
        video_clock_init(&out.clock, w, fps, speed);
        char *mp4 = path_in(dir, "video.mp4");
        rc = mp4 ? video_open(&out.video, mp4, out.picture.width, out.picture.height, fps) : -1;
        free(mp4);
        if (rc)
            goto fail;
    }
    out.open = 1;
    return 0;
fail:
    close_all();
    return -1;
}

int output_sample_add(const output_sample *s)
{
    if (!out.open)
        return -1;
    int rc = 0;
    if (tables_add(&out.tables, out.world, s))
        rc = -1;
    if (ir_table_add(&out.ir, out.world->n_robots, s))
        rc = -1;
    if (history_add(&out.history, s)) {
        fprintf(stderr, "openswarm-sim: out of memory keeping the run for %s/viewer.html at "
                        "%.3f s; give a longer sample period\n",
                out.dir, s->time_s);
        rc = -1;
    }
    if (rc)
        out.failed = 1;
    return rc;
}

double output_next_frame_s(void)
{
    return out.open && out.options.video ? video_clock_next_s(&out.clock) : INFINITY;
}

double output_frame_after_s(double t)
{
    return out.open && out.options.video ? video_clock_after_s(&out.clock, t) : INFINITY;
}

int output_frame_add(const output_sample *s)
{
    if (!out.open || !out.options.video)
        return -1;
    int frames = video_clock_add(&out.clock, s);
    if (frames < 0) {
        fprintf(stderr, "openswarm-sim: out of memory keeping the video's trails at %.3f s; give "
                        "a lower --video-fps\n",
                s->time_s);
        out.failed = 1;
        return -1;
    }
    if (frames > 0)
        picture_draw(&out.picture, &out.clock.points, out.clock.points.n - 1);
    for (int k = 0; k < frames; k++)
        if (video_frame(&out.video, out.picture.surface)) {
            out.failed = 1;
            return -1;
        }
    return 0;
}

/* Writes one file that is written whole at the end, under path.part, then
 * renamed (part_file.c); 0 when it is in place. */
static int write_whole(const char *path, int (*write)(const char *part))
{
    char *part = path ? part_file_name(path) : NULL;
    int rc = part ? write(part) : -1;
    free(part);
    return path ? part_file_finish(path, rc == 0) : -1;
}

static int write_picture(const char *part)
{
    return picture_write_png(&out.picture, part);
}

static int write_viewer(const char *part)
{
    return viewer_write(part, &out.history);
}

/* Appends ", name" (or "name" first) to the list of written files. */
static void list_add(char *list, size_t size, const char *path)
{
    size_t n = strlen(list);
    snprintf(list + n, size - n, "%s%s", n ? ", " : "", path);
}

int output_close(void)
{
    if (!out.open)
        return -1;
    int rc = out.failed ? -1 : 0;
    char *path;
    written[0] = 0;

    if (tables_close(&out.tables, 1) == 0) {
        path = path_in(out.dir, "trajectories.csv");
        list_add(written, sizeof written, path);
        free(path);
        path = path_in(out.dir, "objects.csv");
        list_add(written, sizeof written, path);
        free(path);
    } else {
        rc = -1;
    }
    if (out.ir.file) {
        path = path_in(out.dir, "ir.csv");
        if (ir_table_close(&out.ir, 1) == 0)
            list_add(written, sizeof written, path);
        else
            rc = -1;
        free(path);
    }

    out.picture.trail_s = INFINITY; /* where they went, start to end */
    out.picture.starts = 1;
    picture_draw(&out.picture, &out.history, out.history.n - 1);
    path = path_in(out.dir, "final.png");
    if (write_whole(path, write_picture) == 0)
        list_add(written, sizeof written, path);
    else
        rc = -1;
    free(path);

    if (out.options.video) {
        /* ffmpeg makes no file of no frames: a run shorter than a frame
         * shows its end. */
        if (out.video.frames == 0)
            video_frame(&out.video, out.picture.surface);
        path = path_in(out.dir, "video.mp4");
        if (video_close(&out.video) == 0 && path)
            list_add(written, sizeof written, path);
        else
            rc = -1;
        free(path);
    }

    path = path_in(out.dir, "viewer.html");
    if (write_whole(path, write_viewer) == 0)
        list_add(written, sizeof written, path);
    else
        rc = -1;
    free(path);

    if (!out.options.quiet && written[0])
        fprintf(stderr, "openswarm-sim: wrote %s\n", written);
    close_all();
    return rc;
}

const char *output_written(void)
{
    return written;
}

void output_quieten(void)
{
    out.options.quiet = 1;
}
