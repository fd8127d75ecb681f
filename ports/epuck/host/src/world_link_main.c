/* The process the world simulator starts for one e-puck: the app runs on
 * the host port's simulated CPU with a manual clock, and this thread plays
 * the robot's hardware for the world, one exchange per world step
 * (openswarm/epuck_world_link.h): apply the step's inputs as interrupts,
 * run advance_ms ticks, wait until every thread blocks, answer with the
 * outputs. Nothing depends on the host's speed, so a run is repeatable.
 *
 * Exit status: 0 after the world's stop, 2 when the link breaks (end of
 * input, a bad message, a failed write). */
#define _GNU_SOURCE
#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "board_world.h"
#include "link_io.h"
#include "openswarm/epuck_world_app.h"
#include "openswarm/epuck_world_link.h"
#include "openswarm/host.h"

/* The structs go over the link as they are in memory. */
_Static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "the link is little-endian");
_Static_assert(sizeof(epuck_world_input) == 48, "epuck_world_input has no padding");
_Static_assert(sizeof(epuck_world_output) == 20, "epuck_world_output has no padding");

#define MAX_FRAME_PIXELS (640u * 480u)
/* Wall-clock time the robot gets to finish a step's work (handlers,
 * threads woken) before it answers: far more than any controller needs. */
#define IDLE_TIMEOUT_MS 2000u

static uint16_t frame[MAX_FRAME_PIXELS];
static int link_out; /* the original standard output */

static void link_broken(const char *what, ...) __attribute__((format(printf, 1, 2), noreturn));

static void link_broken(const char *what, ...) {
    va_list args;
    va_start(args, what);
    fputs("epuck world link: ", stderr);
    vfprintf(stderr, what, args);
    fputc('\n', stderr);
    va_end(args);
    exit(2);
}

/* The link keeps the original standard output; the app's printf goes to
 * standard error instead, where it cannot corrupt a message. */
static void take_stdout(void) {
    link_out = dup(STDOUT_FILENO);
    if (link_out < 0 || dup2(STDERR_FILENO, STDOUT_FILENO) < 0) link_broken("cannot set up stdout");
    setvbuf(stdout, NULL, _IOLBF, 0);
}

/* Let the robot finish what the step started. A thread that never blocks
 * keeps the CPU from idling: then the answer depends on the host's timing,
 * which is said once, and later steps do not wait for it again. */
static void settle(void) {
    static bool busy;
    if (host_cpu_wait_idle(busy ? 0 : IDLE_TIMEOUT_MS) || busy) return;
    busy = true;
    fprintf(stderr, "epuck world link: the robot was not idle %u ms after a step (a thread that "
                    "never blocks?): its answers now depend on the host's timing\n", IDLE_TIMEOUT_MS);
}

static void answer(void) {
    epuck_world_output out;
    board_world_report(&out);
    if (!link_write(link_out, &out, sizeof out)) link_broken("cannot write an output to the world");
}

static void read_input(epuck_world_input *in) {
    size_t got = link_read(STDIN_FILENO, in, sizeof *in);
    if (got != sizeof *in)
        link_broken("the input ended after %zu of an epuck_world_input's %zu bytes", got, sizeof *in);
    if (in->magic != EPUCK_LINK_MAGIC)
        link_broken("an input begins with 0x%08X, not the magic 0x%08X (\"EPK1\")",
                    (unsigned)in->magic, (unsigned)EPUCK_LINK_MAGIC);
}

/* The frame's pixels, which follow the input; its size in pixels. */
static size_t read_frame(const epuck_world_input *in) {
    size_t pixels = (size_t)in->frame_width * in->frame_height;
    if (pixels > MAX_FRAME_PIXELS)
        link_broken("a frame of %u x %u pixels is larger than 640 x 480", in->frame_width,
                    in->frame_height);
    size_t got = link_read(STDIN_FILENO, frame, pixels * sizeof frame[0]);
    if (got != pixels * sizeof frame[0])
        link_broken("the input ended after %zu of a %u x %u frame's %zu bytes", got,
                    in->frame_width, in->frame_height, pixels * sizeof frame[0]);
    return pixels;
}

static void apply(const epuck_world_input *in) {
    board_world_deliver_selector((uint8_t)in->selector);
    if (in->flags & EPUCK_LINK_PROXIMITY) {
        epuck_proximity_samples samples;
        memcpy(samples.off, in->proximity_off, sizeof samples.off);
        memcpy(samples.pulsed, in->proximity_pulsed, sizeof samples.pulsed);
        board_world_deliver_proximity(&samples);
    }
    if (in->frame_width != 0 && read_frame(in) != 0)
        board_world_deliver_frame(frame, in->frame_width, in->frame_height);
}

int main(void) {
    take_stdout();
    host_cpu_start_main(HOST_CLOCK_MANUAL, openswarm_robot_main);
    settle();
    answer(); /* time 0: the world knows the robot is up */
    for (;;) {
        epuck_world_input in;
        read_input(&in);
        apply(&in);
        host_cpu_advance(in.advance_ms);
        settle();
        answer();
        if (in.flags & EPUCK_LINK_STOP) break;
    }
    host_cpu_stop();
    return 0;
}
