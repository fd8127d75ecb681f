/* The e-puck's board in the native mode, at message level: each step the
 * simulator sets the world's sensors in the robot's native_epuck_io and
 * they arrive as one interrupt - the selector (when it changed), the
 * proximity samples, the camera frame, in the order the pipe mode's board
 * delivers them (ports/epuck/host/src/board_world.c) - and what the
 * device layer last set (world_outputs.c, shared with that board) is
 * copied out whenever the robot yields. So a controller gets the same
 * inputs in the same order in both modes. */
#include "native_internal.h"

#include <string.h>

#include "../../../epuck/src/epuck_board.h"
#include "openswarm/native_epuck.h"
#include "openswarm/robot.h"
#include "world_outputs.h"

static uint8_t started;      /* the devices are there to take inputs */
static int16_t last_selector = -1; /* none delivered yet */

static native_epuck_io *board(void) { return native_io_of_robot->board; }

void epuck_board_start(void) { started = 1; }

/* Never: an e-puck has no Kilobot inbox. */
void native_ir_interrupt(void) {}

void native_board_inputs(void) {
    const epuck_world_input *in = &board()->input;
    if (!started) return; /* as the pipe mode's board: before the devices, nothing to tell */
    os_isr_enter();
    if ((int16_t)in->selector != last_selector) {
        last_selector = (int16_t)in->selector;
        epuck_selector_arrived((uint8_t)in->selector);
    }
    if (in->flags & EPUCK_LINK_PROXIMITY) {
        epuck_proximity_samples samples;
        memcpy(samples.off, in->proximity_off, sizeof samples.off);
        memcpy(samples.pulsed, in->proximity_pulsed, sizeof samples.pulsed);
        epuck_proximity_arrived(&samples);
    }
    if (in->frame_width != 0 && in->frame_height != 0) {
        epuck_camera_frame frame = {board()->pixels, in->frame_width, in->frame_height, 0};
        epuck_camera_arrived(&frame);
    }
    os_isr_exit();
}

int native_outputs_report(void) {
    world_outputs_shown(&board()->shown);
    return 1;
}

/* The kernel's tick has no board hooks on the e-puck. */
void native_board_tick(void) { os_tick(); }
int native_board_tick_hooked(void) { return 0; }
int native_board_tick_needed(void) { return 0; }
void native_board_elapsed(uint16_t ms) { (void)ms; }
void native_board_power_up(void) {}

uint16_t epuck_robot_id(void) { return board()->robot_id; }
/* printf goes to the simulator's standard output as it is (the host's). */
void epuck_console_init(void) {}
