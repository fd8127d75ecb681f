/* The world link for a controller without the OS (openswarm/epuck_plain.h):
 * the program's own loop drives the exchange. Each input is answered once
 * the program has had its say: at once for a step without a frame; for a
 * step with one, when the program asks for the next frame (it has set its
 * wheels from this one by then). */
#define _GNU_SOURCE
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "link_io.h"
#include "openswarm/epuck_plain.h"
#include "openswarm/epuck_world_link.h"

static uint16_t pixels[EPUCK_LINK_MAX_PIXELS];
static epuck_camera_frame frame = {pixels, 0, 0, 0};
static int link_out;
static uint32_t now_ms;
static int16_t wheel[2];
static bool owed; /* an input is still to be answered */

static void __attribute__((noreturn)) broken(const char *what) {
    fprintf(stderr, "epuck plain link: %s\n", what);
    exit(2);
}

static void answer(void) {
    epuck_world_output out = {EPUCK_LINK_MAGIC, now_ms, wheel[0], wheel[1], 0, 0, 0, 0, 0};
    if (!link_write(link_out, &out, sizeof out)) broken("cannot write an output to the world");
    owed = false;
}

static void read_input(epuck_world_input *in) {
    const char *why = link_read_input(STDIN_FILENO, in, pixels);
    if (why != NULL) broken(why);
}

void epuck_plain_start(void) {
    link_out = link_take_stdout();
    if (link_out < 0) broken("cannot set up stdout");
    answer(); /* time 0: up */
}

const epuck_camera_frame *epuck_plain_wait_frame(void) {
    for (;;) {
        if (owed) answer();
        epuck_world_input in;
        read_input(&in);
        now_ms += in.advance_ms;
        owed = true;
        if (in.flags & EPUCK_LINK_STOP) {
            answer();
            exit(0);
        }
        if (in.frame_width != 0 && in.frame_height != 0) {
            frame.width = in.frame_width;
            frame.height = in.frame_height;
            return &frame;
        }
    }
}

void epuck_plain_set_wheels(int16_t left, int16_t right) {
    wheel[0] = epuck_plain_limit(left);
    wheel[1] = epuck_plain_limit(right);
}
