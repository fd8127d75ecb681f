/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* --faults in the native mode (native_faults.h).
 *
 * A reset is the path kilobot_restart takes (NATIVE_RESTART): the robot's
 * RAM image as loaded, which is what the AVR's start-up code makes of the
 * RAM it keeps (.data copied, .bss cleared), its stacks afresh, its clock
 * running on. A brown-out stops it where it is: it runs no more, hears
 * nothing, shows nothing and its motors stop, until the power returns at
 * the end of the window that reaches it; then it starts from reset. Both
 * come between windows (1 ms apart here, 8 us in the exact mode), at the
 * times the exact mode's plan draws. */
#include "native/native_faults.h"

#include <stdlib.h>

#include "faults/faults.h"
#include "native/native_frame_faults.h"
#include "native/native_swarm.h"
#include "world/world_run.h"

static int in_world;
static uint32_t nominal;
static uint64_t *off_until; /* nominal cycles; 0: powered */

int native_faults_start(const options *o) {
    if (o->faults == NULL) return 0;
    off_until = calloc((size_t)o->robots, sizeof *off_until);
    if (off_until == NULL || faults_start(o->faults, o->robots) != 0) return -1;
    in_world = o->world != NULL;
    const fault_spec *f = o->faults;
    return native_frame_faults_start(f->flip_pct, f->cut_pct, f->seed, o->robots);
}

static uint64_t own_cycle(int i, uint64_t nominal_cycle) {
    uint32_t hz = native_swarm_robot(i)->hz;
    return hz == nominal ? nominal_cycle : nominal_cycle * hz / nominal;
}

/* The world sees its motors stop at once (it keeps the last duties a
 * robot reported; the robot, started again, reports none until it moves). */
static void motors_stop(int i, uint64_t now) {
    if (in_world) world_run_motors(i, 0, 0, (double)now / nominal);
}

static int can_fault(int i) {
    return native_swarm_robot(i)->io->state == NATIVE_RUNNING && off_until[i] == 0;
}

static avr_cycle_count_t powered_at(int i) { return off_until[i]; }

static void reset(int i, avr_cycle_count_t now) {
    native_swarm_restart(i, own_cycle(i, now));
    motors_stop(i, now);
}

static void power_off(int i, avr_cycle_count_t now, avr_cycle_count_t on) {
    off_until[i] = on;
    native_swarm_power_off(i);
    motors_stop(i, now);
}

static void power_on(int i, avr_cycle_count_t on) {
    off_until[i] = 0;
    native_swarm_restart(i, own_cycle(i, on));
}

void native_faults_attach(uint32_t nominal_hz) {
    static const fault_robots native = {can_fault, powered_at, reset, power_off, power_on};
    if (off_until == NULL) return;
    nominal = nominal_hz;
    faults_attach(&native, nominal_hz);
}

void native_faults_after_window(uint64_t end) {
    if (off_until == NULL) return;
    if (native_frame_faults_on()) native_frame_faults_log();
    faults_after_window(end);
}
