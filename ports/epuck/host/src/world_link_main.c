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
_Static_assert(sizeof(epuck_world_losses) == 28, "epuck_world_losses has no padding");

/* Wall-clock time the robot gets to finish a step's work (handlers,
 * threads woken) before it answers: far more than any controller needs. */
#define IDLE_TIMEOUT_MS 2000u

static uint16_t frame[EPUCK_LINK_MAX_PIXELS];
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
    const char *why = link_read_input(STDIN_FILENO, in, frame);
    if (why != NULL) link_broken("%s", why);
}

static void apply(const epuck_world_input *in) {
    board_world_deliver_selector((uint8_t)in->selector);
    if (in->flags & EPUCK_LINK_PROXIMITY) {
        epuck_proximity_samples samples;
        memcpy(samples.off, in->proximity_off, sizeof samples.off);
        memcpy(samples.pulsed, in->proximity_pulsed, sizeof samples.pulsed);
        board_world_deliver_proximity(&samples);
    }
    if (in->frame_width != 0 && in->frame_height != 0)
        board_world_deliver_frame(frame, in->frame_width, in->frame_height);
}

int main(void) {
    link_out = link_take_stdout();
    if (link_out < 0) link_broken("cannot set up stdout");
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
    epuck_world_losses losses;
    board_world_losses(&losses);
    if (!link_write(link_out, &losses, sizeof losses)) link_broken("cannot write the losses to the world");
    host_cpu_stop();
    return 0;
}
