/* The e-puck's lower layer (ports/epuck/src/epuck_board.h) for a robot in
 * the world simulator: what the device layer writes is kept for the next
 * answer to the world, and what the world senses for the robot arrives
 * as interrupts on the simulated CPU, as a real board's sensors do. */
#include "board_world.h"

#include "../../src/epuck_board.h"
#include "openswarm/fault.h"
#include "openswarm/host.h"
#include "openswarm/system_time.h"

/* Written by the system thread (the devices' write functions), read in an
 * interrupt on the same CPU: never at the same time. */
static struct {
    int16_t wheel_left, wheel_right;
    uint8_t ring, body, front, rgb;
} shown;
static bool started;

void epuck_board_set_wheels(int16_t left, int16_t right) {
    shown.wheel_left = left;
    shown.wheel_right = right;
}

void epuck_board_set_ring_leds(uint8_t mask) { shown.ring = mask; }
void epuck_board_set_body_led(bool on) { shown.body = on; }
void epuck_board_set_front_led(bool on) { shown.front = on; }
void epuck_board_set_rgb_leds(uint8_t rgb) { shown.rgb = rgb; }

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
    epuck_camera_frame frame = {pixels, width, height};
    host_cpu_interrupt(camera_isr, &frame);
}

/* ---- outputs: read on the CPU ---- */

/* The kernel's faults (sys_fault), not its refused requests. */
static uint32_t faults_so_far(void) {
    sys_stats stats;
    Sys_Get_Stats(&stats);
    return (uint32_t)stats.stack_overflows + stats.critical_leaks + stats.cpu_faults +
           stats.handler_overruns;
}

static void report_isr(void *arg) {
    epuck_world_output *out = arg;
    out->magic = EPUCK_LINK_MAGIC;
    out->time_ms = Sys_Get_SystemTime();
    out->wheel_left = shown.wheel_left;
    out->wheel_right = shown.wheel_right;
    out->ring_leds = shown.ring;
    out->body_led = shown.body;
    out->front_led = shown.front;
    out->rgb_leds = shown.rgb;
    out->faults = faults_so_far();
}

void board_world_report(epuck_world_output *out) { host_cpu_interrupt(report_isr, out); }
