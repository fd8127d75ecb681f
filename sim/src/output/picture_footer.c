/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The strip below the arena: the time at the left, a scale bar at the
 * right and between them a legend of the LEDs at that moment - each
 * colour the robots show, as the app writes it (RGB(r,g,b), channels
 * 0..3), with how many show it, the commonest first. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "output/output_parts.h"
#include "output/picture_style.h"

enum { LED_COLOURS = 64, LEGEND_GAP_PX = 14, SWATCH_RADIUS_PX = 6 };

/* A round length at most 200 pixels long: 1, 2 or 5 times a power of ten. */
static double scale_bar_mm(double scale)
{
    const double want = 200 / scale;
    double step = pow(10, floor(log10(want)));
    if (step * 5 <= want)
        return step * 5;
    if (step * 2 <= want)
        return step * 2;
    return step;
}

static double text_width(cairo_t *cr, const char *text)
{
    cairo_text_extents_t ext;
    cairo_text_extents(cr, text, &ext);
    return ext.x_advance;
}

/* The scale bar ending at `right`; returns where its left end is. */
static double draw_scale_bar(picture *p, double right, double baseline)
{
    cairo_t *cr = p->cr;
    char text[32];
    const double bar_mm = scale_bar_mm(p->scale), bar_px = bar_mm * p->scale;
    if (bar_mm >= 1000)
        snprintf(text, sizeof text, "%g m", bar_mm / 1000);
    else
        snprintf(text, sizeof text, "%g mm", bar_mm);
    const double bar_right = right - text_width(cr, text) - 8;
    cairo_move_to(cr, bar_right + 8, baseline);
    cairo_show_text(cr, text);
    const double y = floor(baseline - 5) + 0.5;
    cairo_set_line_width(cr, 2);
    cairo_move_to(cr, bar_right - bar_px, y - 4);
    cairo_line_to(cr, bar_right - bar_px, y);
    cairo_line_to(cr, bar_right, y);
    cairo_line_to(cr, bar_right, y - 4);
    cairo_stroke(cr);
    return bar_right - bar_px;
}

static int led_key(const output_robot *r)
{
    return (r->led_r & 3) << 4 | (r->led_g & 3) << 2 | (r->led_b & 3);
}

/* The colours shown, commonest first (ties: in RGB order); returns how many. */
static int led_colours(const world_spec *w, const output_robot *robots, int count[LED_COLOURS],
                       int order[LED_COLOURS])
{
    memset(count, 0, LED_COLOURS * sizeof *count);
    for (int i = 0; robots && i < w->n_robots; i++)
        count[led_key(&robots[i])]++;
    if (!robots)
        count[0] = w->n_robots; /* before the first sample: all dark */
    int n = 0;
    for (int key = 0; key < LED_COLOURS; key++) {
        if (!count[key])
            continue;
        int at = n++;
        while (at > 0 && count[order[at - 1]] < count[key]) {
            order[at] = order[at - 1];
            at--;
        }
        order[at] = key;
    }
    return n;
}

static void led_label(int key, int count, char *text, size_t size)
{
    if (key == 0)
        snprintf(text, size, "off: %d", count);
    else
        snprintf(text, size, "RGB(%d,%d,%d): %d", key >> 4, key >> 2 & 3, key & 3, count);
}

static void draw_swatch(cairo_t *cr, int key, double x, double y)
{
    cairo_new_path(cr); /* not joined to the text before it */
    cairo_arc(cr, x, y, SWATCH_RADIUS_PX, 0, 2 * M_PI);
    if (key)
        set(cr, RGB8(led_level_8bit(key >> 4), led_level_8bit(key >> 2 & 3), led_level_8bit(key & 3)));
    else
        set(cr, ROBOT_OFF);
    cairo_fill_preserve(cr);
    set(cr, ROBOT_EDGE);
    cairo_set_line_width(cr, 1);
    cairo_stroke(cr);
}

/* The legend between `left` and `right`: as many colours as fit, then
 * "+N more". */
static void draw_legend(picture *p, const world_spec *w, const output_robot *robots, double left,
                        double right, double baseline)
{
    cairo_t *cr = p->cr;
    int count[LED_COLOURS], order[LED_COLOURS];
    const int n = led_colours(w, robots, count, order);
    char text[48], more[24];
    snprintf(text, sizeof text, "%d robot%s:", w->n_robots, w->n_robots == 1 ? "" : "s");
    double x = left;
    set(cr, TEXT);
    cairo_move_to(cr, x, baseline);
    cairo_show_text(cr, text);
    x += text_width(cr, text) + LEGEND_GAP_PX;
    for (int k = 0; k < n; k++) {
        led_label(order[k], count[order[k]], text, sizeof text);
        const double entry = 2 * SWATCH_RADIUS_PX + 4 + text_width(cr, text);
        snprintf(more, sizeof more, "+%d more", n - k - 1);
        const double reserve = k + 1 < n ? LEGEND_GAP_PX + text_width(cr, more) : 0;
        if (x + entry + reserve > right) {
            snprintf(more, sizeof more, "+%d more", n - k);
            set(cr, TEXT);
            cairo_move_to(cr, x, baseline);
            cairo_show_text(cr, more);
            return;
        }
        draw_swatch(cr, order[k], x + SWATCH_RADIUS_PX, baseline - 5);
        set(cr, TEXT);
        cairo_move_to(cr, x + 2 * SWATCH_RADIUS_PX + 4, baseline);
        cairo_show_text(cr, text);
        x += entry + LEGEND_GAP_PX;
    }
}

void picture_draw_footer(picture *p, const world_spec *w, double time_s, const output_robot *robots)
{
    cairo_t *cr = p->cr;
    cairo_identity_matrix(cr);
    cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, 14);
    const double baseline = p->origin_y + MARGIN_PX + 15;
    char text[32];
    snprintf(text, sizeof text, "t = %.1f s", time_s);
    set(cr, TEXT);
    cairo_move_to(cr, MARGIN_PX, baseline);
    cairo_show_text(cr, text);
    /* The legend starts where the longest time ends: it stays put in a video. */
    snprintf(text, sizeof text, "t = %.1f s", w->duration_s > time_s ? w->duration_s : time_s);
    const double legend_left = MARGIN_PX + text_width(cr, text) + 2 * LEGEND_GAP_PX;
    const double bar_left = draw_scale_bar(p, p->width - MARGIN_PX, baseline);
    cairo_set_font_size(cr, 12);
    draw_legend(p, w, robots, legend_left, bar_left - 2 * LEGEND_GAP_PX, baseline);
}
