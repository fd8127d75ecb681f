/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The picture's layout and colours, shared by the arena (picture.c) and
 * the strip below it (picture_footer.c); tests/world/check_picture.py
 * reads some of them back. */
#ifndef OPENSWARM_PICTURE_STYLE_H
#define OPENSWARM_PICTURE_STYLE_H

#include <cairo.h>

enum { MARGIN_PX = 16, FOOTER_PX = 30, ARENA_LONG_SIDE_PX = 768 };

typedef struct rgb {
    double r, g, b;
} rgb;
#define RGB8(r, g, b) ((rgb){(r) / 255.0, (g) / 255.0, (b) / 255.0})

#define BACKGROUND RGB8(214, 218, 224)
#define FLOOR RGB8(248, 247, 242)
#define GRID RGB8(230, 229, 222)
#define BORDER RGB8(60, 62, 70)
#define OBSTACLE RGB8(80, 80, 88)
#define OBJECT RGB8(205, 55, 45)
#define OBJECT_EDGE RGB8(130, 25, 20)
/* An unlit robot: its dark circuit board, darker than any lit LED's grey. */
#define ROBOT_OFF RGB8(70, 70, 76)
#define ROBOT_EDGE RGB8(25, 25, 30)
#define LIGHT_CORE RGB8(255, 214, 0)
#define LIGHT_EDGE RGB8(190, 120, 0)
#define TEXT RGB8(30, 30, 35)

static inline void set(cairo_t *cr, rgb c)
{
    cairo_set_source_rgb(cr, c.r, c.g, c.b);
}

#endif
