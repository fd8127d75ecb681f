/* The e-puck's lower layer (ports/epuck/src/epuck_board.h) for a robot in
 * the world simulator: what the device layer writes is kept for the next
 * answer to the world, and what the world senses for the robot arrives
 * as interrupts on the simulated CPU, as a real board's sensors do. */
#include "board_world.h"

#include "../../src/epuck_board.h"
#include "openswarm/host.h"
#include "world_outputs.h"

static bool started;

/* The world samples for the board: nothing to start but the note that the
 * devices are there to take its inputs. */
void epuck_board_start(void) { started = true; }

/* ---- inputs: interrupts on the CPU ---- */

static void selector_isr(void *arg) {
    if (started) epuck_selector_arrived(*(const uint8_t *)arg);
}

static void proximity_isr(void *arg) {
    if (started) epuck_proximity_arrived(arg);
}

static void camera_isr(void *arg) {
    if (started) epuck_camera_arrived(arg);
}

void board_world_deliver_selector(uint8_t position) {
    static int last = -1; /* none delivered yet */
    if (position == last) return;
    last = position;
    host_cpu_interrupt(selector_isr, &position);
}

void board_world_deliver_proximity(const epuck_proximity_samples *samples) {
    host_cpu_interrupt(proximity_isr, (void *)samples);
}

void board_world_deliver_frame(const uint16_t *pixels, uint16_t width, uint16_t height) {
    epuck_camera_frame frame = {pixels, width, height, 0};
    host_cpu_interrupt(camera_isr, &frame);
}

/* ---- outputs: read on the CPU ---- */

static void report_isr(void *arg) { world_outputs_fill(arg); }

void board_world_report(epuck_world_output *out) { host_cpu_interrupt(report_isr, out); }

static void losses_isr(void *arg) { world_outputs_losses(arg); }

void board_world_losses(epuck_world_losses *out) { host_cpu_interrupt(losses_isr, out); }
