#include "world_outputs.h"

#include "../../src/epuck_board.h"
#include "openswarm/fault.h"
#include "openswarm/system_time.h"

#include <stddef.h>
#include <string.h>

/* Written by the system thread (the devices' write functions), read on
 * the same CPU when the world is answered: never at the same time. */
static struct {
    int16_t wheel_left, wheel_right;
    uint8_t ring, body, front, rgb;
} shown;

void epuck_board_set_wheels(int16_t left, int16_t right) {
    shown.wheel_left = left;
    shown.wheel_right = right;
}

void epuck_board_set_ring_leds(uint8_t mask) { shown.ring = mask; }
void epuck_board_set_body_led(bool on) { shown.body = on; }
void epuck_board_set_front_led(bool on) { shown.front = on; }
void epuck_board_set_rgb_leds(uint8_t rgb) { shown.rgb = rgb; }

/* The kernel's faults (sys_fault), not its refused requests. */
static uint32_t faults_so_far(void) {
    sys_stats stats;
    Sys_Get_Stats(&stats);
    return (uint32_t)stats.stack_overflows + stats.critical_leaks + stats.cpu_faults +
           stats.handler_overruns;
}

/* sys_stats begins with its uint16_t counters, in the link's order. */
_Static_assert(offsetof(sys_stats, event_queue_peak) == EPUCK_LINK_LOSS_COUNTERS * sizeof(uint16_t),
               "sys_stats' counters are the link's");

void world_outputs_losses(epuck_world_losses *out) {
    sys_stats stats;
    Sys_Get_Stats(&stats);
    out->magic = EPUCK_LINK_LOSSES_MAGIC;
    memcpy(out->counters, &stats, sizeof out->counters);
}

void world_outputs_fill(epuck_world_output *out) {
    world_outputs_shown(out);
    out->time_ms = Sys_Get_SystemTime();
    out->faults = faults_so_far();
}

void world_outputs_shown(epuck_world_output *out) {
    out->magic = EPUCK_LINK_MAGIC;
    out->wheel_left = shown.wheel_left;
    out->wheel_right = shown.wheel_right;
    out->ring_leds = shown.ring;
    out->body_led = shown.body;
    out->front_led = shown.front;
    out->rgb_leds = shown.rgb;
}
