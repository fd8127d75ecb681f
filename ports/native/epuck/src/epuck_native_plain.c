/* The world link for a controller without the OS (openswarm/epuck_plain.h)
 * in the native mode: the program's loop sleeps until a step brings a
 * camera frame (the board's interrupt, native_io.board_inputs), and its
 * wheels are shown to the simulator whenever it yields. As in the pipe
 * mode (ports/epuck/host/src/plain_world.c), the wheels set from a step's
 * frame are the step's answer. The kernel is linked (the native port's
 * clock calls it) but never started: no tick, nothing but the world's
 * inputs wakes the program. */
#include "native_internal.h"

#include "openswarm/epuck_plain.h"
#include "openswarm/native_epuck.h"

static epuck_camera_frame frame;
static uint8_t frame_arrived;
static int16_t wheel[2];

static native_epuck_io *board(void) { return native_io_of_robot->board; }

void native_board_inputs(void) {
    const epuck_world_input *in = &board()->input;
    if (in->frame_width == 0 || in->frame_height == 0) return;
    frame = (epuck_camera_frame){board()->pixels, in->frame_width, in->frame_height, 0};
    frame_arrived = 1;
}

void epuck_plain_start(void) { port_init(); /* interrupts masked, no tick */ }

const epuck_camera_frame *epuck_plain_wait_frame(void) {
    frame_arrived = 0;
    while (!frame_arrived) port_idle();
    return &frame;
}

void epuck_plain_set_wheels(int16_t left, int16_t right) {
    wheel[0] = epuck_plain_limit(left);
    wheel[1] = epuck_plain_limit(right);
}

int native_outputs_report(void) {
    board()->shown = (epuck_world_output){EPUCK_LINK_MAGIC, 0, wheel[0], wheel[1], 0, 0, 0, 0, 0};
    return 1;
}

/* Nothing of the Kilobot's, nor the kernel's tick (never started). */
void native_ir_interrupt(void) {}
void native_board_tick(void) {}
int native_board_tick_hooked(void) { return 0; }
int native_board_tick_needed(void) { return 0; }
void native_board_elapsed(uint16_t ms) { (void)ms; }
void native_board_power_up(void) {}
