/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* One frame of the world seen from above, drawn with Cairo: final.png is
 * the last sample's, with every robot's start and whole path, video.mp4
 * is every sample's, with the last 15 s of the paths. The arena's long side
 * takes 768 pixels; a strip below it holds the time, the LEDs' legend and
 * a scale bar (picture_footer.c), so none ever hides a robot. y points up in the world and down in the
 * image. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "output/output_parts.h"
#include "output/picture_style.h"

int picture_init(picture *p, const world_spec *w)
{
    memset(p, 0, sizeof *p);
    const double long_side = w->width_mm > w->height_mm ? w->width_mm : w->height_mm;
    p->scale = ARENA_LONG_SIDE_PX / long_side;
    p->width = (int)ceil(w->width_mm * p->scale) + 2 * MARGIN_PX;
    p->height = (int)ceil(w->height_mm * p->scale) + 2 * MARGIN_PX + FOOTER_PX;
    p->width += p->width & 1;
    p->height += p->height & 1;
    p->origin_x = MARGIN_PX;
    p->origin_y = MARGIN_PX + w->height_mm * p->scale;
    p->robot_radius_mm = world_robot_radius(w);
    p->surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, p->width, p->height);
    if (cairo_surface_status(p->surface) != CAIRO_STATUS_SUCCESS) {
        fprintf(stderr, "openswarm-sim: cannot make a %dx%d picture: %s\n", p->width, p->height,
                cairo_status_to_string(cairo_surface_status(p->surface)));
        cairo_surface_destroy(p->surface);
        p->surface = NULL;
        return -1;
    }
    p->cr = cairo_create(p->surface);
    return 0;
}

void picture_to_pixel(const picture *p, double x_mm, double y_mm, double *px, double *py)
{
    *px = p->origin_x + x_mm * p->scale;
    *py = p->origin_y - y_mm * p->scale;
}

/* From here on the drawing is in world millimetres, y up. */
static void world_coordinates(picture *p)
{
    cairo_identity_matrix(p->cr);
    cairo_translate(p->cr, p->origin_x, p->origin_y);
    cairo_scale(p->cr, p->scale, -p->scale);
}

/* Line widths are given in pixels whatever the scale. */
static void line_px(picture *p, double px)
{
    cairo_set_line_width(p->cr, px / p->scale);
}

static void draw_floor(picture *p, const world_spec *w)
{
    cairo_t *cr = p->cr;
    cairo_identity_matrix(cr);
    set(cr, BACKGROUND);
    cairo_paint(cr);
    world_coordinates(p);
    cairo_rectangle(cr, 0, 0, w->width_mm, w->height_mm);
    set(cr, FLOOR);
    cairo_fill(cr);
    /* A 100 mm grid, faint: distances can be judged by eye. */
    set(cr, GRID);
    line_px(p, 1);
    for (double x = 100; x < w->width_mm; x += 100) {
        cairo_move_to(cr, x, 0);
        cairo_line_to(cr, x, w->height_mm);
    }
    for (double y = 100; y < w->height_mm; y += 100) {
        cairo_move_to(cr, 0, y);
        cairo_line_to(cr, w->width_mm, y);
    }
    cairo_stroke(cr);
}

static void draw_border(picture *p, const world_spec *w)
{
    world_coordinates(p);
    cairo_rectangle(p->cr, 0, 0, w->width_mm, w->height_mm);
    set(p->cr, BORDER);
    line_px(p, 2);
    cairo_stroke(p->cr);
}

static void draw_light_glows(picture *p, const world_spec *w)
{
    cairo_t *cr = p->cr;
    world_coordinates(p);
    cairo_save(cr);
    cairo_rectangle(cr, 0, 0, w->width_mm, w->height_mm); /* light falls on the floor only */
    cairo_clip(cr);
    for (int i = 0; i < w->n_lights; i++) {
        const world_point c = w->lights[i].at;
        cairo_pattern_t *glow = cairo_pattern_create_radial(c.x, c.y, 0, c.x, c.y, 100);
        cairo_pattern_add_color_stop_rgba(glow, 0, 1.0, 0.86, 0.2, 0.55);
        cairo_pattern_add_color_stop_rgba(glow, 0.5, 1.0, 0.9, 0.35, 0.2);
        cairo_pattern_add_color_stop_rgba(glow, 1, 1.0, 0.95, 0.5, 0.0);
        cairo_set_source(cr, glow);
        cairo_arc(cr, c.x, c.y, 100, 0, 2 * M_PI);
        cairo_fill(cr);
        cairo_pattern_destroy(glow);
    }
    cairo_restore(cr);
}

/* A small sun: the light's place, above the obstacles, below the robots. */
static void draw_light_marks(picture *p, const world_spec *w)
{
    cairo_t *cr = p->cr;
    world_coordinates(p);
    const double core = 6 / p->scale, ray_in = 9 / p->scale, ray_out = 14 / p->scale;
    for (int i = 0; i < w->n_lights; i++) {
        const world_point c = w->lights[i].at;
        set(cr, LIGHT_EDGE);
        line_px(p, 1.5);
        for (int k = 0; k < 8; k++) {
            const double a = k * M_PI / 4;
            cairo_move_to(cr, c.x + ray_in * cos(a), c.y + ray_in * sin(a));
            cairo_line_to(cr, c.x + ray_out * cos(a), c.y + ray_out * sin(a));
        }
        cairo_stroke(cr);
        cairo_arc(cr, c.x, c.y, core, 0, 2 * M_PI);
        set(cr, LIGHT_CORE);
        cairo_fill_preserve(cr);
        set(cr, LIGHT_EDGE);
        cairo_stroke(cr);
    }
}

static void draw_obstacles(picture *p, const world_spec *w)
{
    cairo_t *cr = p->cr;
    world_coordinates(p);
    for (int i = 0; i < w->n_obstacles; i++) {
        const world_obstacle *o = &w->obstacles[i];
        for (int k = 0; k < o->n; k++)
            (k ? cairo_line_to : cairo_move_to)(cr, o->v[k].x, o->v[k].y);
        cairo_close_path(cr);
    }
    set(cr, OBSTACLE);
    cairo_fill(cr);
}

static void draw_objects(picture *p, const world_spec *w, const world_point *at)
{
    cairo_t *cr = p->cr;
    world_coordinates(p);
    line_px(p, 1.5);
    for (int i = 0; i < w->n_objects; i++) {
        const world_point c = at ? at[i] : w->objects[i].at;
        cairo_new_sub_path(cr);
        cairo_arc(cr, c.x, c.y, w->objects[i].radius_mm, 0, 2 * M_PI);
        set(cr, OBJECT);
        cairo_fill_preserve(cr);
        set(cr, OBJECT_EDGE);
        cairo_stroke(cr);
    }
}

/* Each robot's path over the last trail_s seconds (all of it in
 * final.png), faint. */
static void draw_trails(picture *p, const output_history *h, int k)
{
    cairo_t *cr = p->cr;
    const int nr = h->world->n_robots;
    const double trail_s = p->trail_s > 0 ? p->trail_s : VIDEO_TRAIL_S;
    if (k < 1)
        return;
    int first = k;
    while (first > 0 && h->time_s[k] - h->time_s[first - 1] <= trail_s)
        first--;
    world_coordinates(p);
    line_px(p, 1.5);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_set_source_rgba(cr, 0.25, 0.3, 0.45, 0.35);
    for (int i = 0; i < nr; i++) {
        for (int j = first; j <= k; j++) {
            const output_robot *r = &history_robots(h, j)[i];
            (j == first ? cairo_move_to : cairo_line_to)(cr, r->x_mm, r->y_mm);
        }
        cairo_stroke(cr);
    }
}

/* Where each robot started: a dashed ring its size, so the trail from it
 * reads as "from here to there". */
static void draw_starts(picture *p, const world_spec *w)
{
    cairo_t *cr = p->cr;
    const double dash = 3 / p->scale;
    world_coordinates(p);
    line_px(p, 1.5);
    cairo_set_dash(cr, &dash, 1, 0);
    set(cr, ROBOT_EDGE);
    for (int i = 0; i < w->n_robots; i++) {
        cairo_new_sub_path(cr);
        cairo_arc(cr, w->robots[i].at.x, w->robots[i].at.y, p->robot_radius_mm, 0, 2 * M_PI);
    }
    cairo_stroke(cr);
    cairo_set_dash(cr, NULL, 0, 0);
}

/* Each robot's number (trajectories.csv's `robot`) above its right side,
 * dark on a white halo so that it reads on any floor and any LED. */
static void draw_ids(picture *p, const world_spec *w, const output_robot *robots)
{
    cairo_t *cr = p->cr;
    cairo_identity_matrix(cr);
    cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
    cairo_set_font_size(cr, 11);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    for (int i = 0; i < w->n_robots; i++) {
        const world_point at = robots ? (world_point){robots[i].x_mm, robots[i].y_mm} : w->robots[i].at;
        double px, py;
        picture_to_pixel(p, at.x + 0.7 * p->robot_radius_mm, at.y + 0.7 * p->robot_radius_mm, &px, &py);
        char text[16];
        snprintf(text, sizeof text, "%d", i);
        cairo_move_to(cr, px + 1, py - 1);
        cairo_text_path(cr, text);
        cairo_set_source_rgb(cr, 1, 1, 1);
        cairo_set_line_width(cr, 3);
        cairo_stroke_preserve(cr);
        set(cr, TEXT);
        cairo_fill(cr);
    }
}

static void draw_robot(picture *p, const output_robot *r)
{
    cairo_t *cr = p->cr;
    const double R = p->robot_radius_mm;
    const int on = r->led_r || r->led_g || r->led_b;
    cairo_arc(cr, r->x_mm, r->y_mm, R, 0, 2 * M_PI);
    if (on)
        set(cr, RGB8(led_level_8bit(r->led_r), led_level_8bit(r->led_g), led_level_8bit(r->led_b)));
    else
        set(cr, ROBOT_OFF);
    cairo_fill_preserve(cr);
    set(cr, ROBOT_EDGE);
    line_px(p, 1.5);
    cairo_stroke(cr);
    /* The heading: from a third of the radius to the rim, dark under light
     * so that it shows on every LED colour; the centre keeps the LED's. */
    const double a = r->heading_deg * M_PI / 180, c = cos(a), s = sin(a);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
    cairo_move_to(cr, r->x_mm + 0.4 * R * c, r->y_mm + 0.4 * R * s);
    cairo_line_to(cr, r->x_mm + 0.92 * R * c, r->y_mm + 0.92 * R * s);
    set(cr, ROBOT_EDGE);
    line_px(p, 3.5);
    cairo_stroke_preserve(cr);
    cairo_set_source_rgb(cr, 1, 1, 1);
    line_px(p, 1.5);
    cairo_stroke(cr);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
}

static void draw_robots(picture *p, const world_spec *w, const output_robot *robots)
{
    world_coordinates(p);
    for (int i = 0; i < w->n_robots; i++) {
        output_robot r;
        if (robots) {
            r = robots[i];
        } else {
            memset(&r, 0, sizeof r);
            r.x_mm = w->robots[i].at.x;
            r.y_mm = w->robots[i].at.y;
            r.heading_deg = w->robots[i].heading_deg;
        }
        draw_robot(p, &r);
    }
}

/* What never moves (floor, grid, the lights' glow, obstacles) is drawn
 * once and painted under every frame: a video redraws it 30 times a second
 * of output, and the glow's gradient alone is a large share of a frame. */
static int draw_background(picture *p, const world_spec *w)
{
    if (p->background)
        return 0;
    cairo_t *frame_cr = p->cr;
    cairo_surface_t *bg = cairo_image_surface_create(CAIRO_FORMAT_RGB24, p->width, p->height);
    if (cairo_surface_status(bg) != CAIRO_STATUS_SUCCESS) {
        cairo_surface_destroy(bg);
        return -1;
    }
    p->cr = cairo_create(bg);
    draw_floor(p, w);
    draw_light_glows(p, w);
    draw_obstacles(p, w);
    cairo_destroy(p->cr);
    p->cr = frame_cr;
    cairo_surface_flush(bg);
    p->background = bg;
    return 0;
}

void picture_draw(picture *p, const output_history *h, int k)
{
    const world_spec *w = h->world;
    cairo_save(p->cr);
    if (draw_background(p, w) == 0) {
        cairo_identity_matrix(p->cr);
        cairo_set_source_surface(p->cr, p->background, 0, 0);
        cairo_set_operator(p->cr, CAIRO_OPERATOR_SOURCE);
        cairo_paint(p->cr);
        cairo_set_operator(p->cr, CAIRO_OPERATOR_OVER);
    } else {
        draw_floor(p, w);
        draw_light_glows(p, w);
        draw_obstacles(p, w);
    }
    const output_robot *robots = k >= 0 ? history_robots(h, k) : NULL;
    if (p->starts)
        draw_starts(p, w);
    if (k >= 0)
        draw_trails(p, h, k);
    draw_light_marks(p, w);
    draw_objects(p, w, k >= 0 ? history_objects(h, k) : NULL);
    draw_robots(p, w, robots);
    if (p->ids)
        draw_ids(p, w, robots);
    draw_border(p, w);
    picture_draw_footer(p, w, k >= 0 ? h->time_s[k] : 0.0, robots);
    cairo_restore(p->cr);
    cairo_surface_flush(p->surface);
}

int picture_write_png(picture *p, const char *path)
{
    cairo_status_t st = cairo_surface_write_to_png(p->surface, path);
    if (st != CAIRO_STATUS_SUCCESS) {
        fprintf(stderr, "openswarm-sim: cannot write %s: %s; choose another --out folder\n", path,
                st == CAIRO_STATUS_WRITE_ERROR && errno ? strerror(errno)
                                                        : cairo_status_to_string(st));
        return -1;
    }
    return 0;
}

void picture_free(picture *p)
{
    if (p->cr)
        cairo_destroy(p->cr);
    if (p->background)
        cairo_surface_destroy(p->background);
    if (p->surface)
        cairo_surface_destroy(p->surface);
    memset(p, 0, sizeof *p);
}
