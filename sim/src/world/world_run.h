/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* A run in a world (--world FILE): what the file sets of the options, the
 * robots' bodies moving with their motors, the IR channel and the light
 * sensors following them, and the outputs sampled as it goes. */
#ifndef OPENSWARM_WORLD_RUN_H
#define OPENSWARM_WORLD_RUN_H

#include "sim.h"
#include "output/output.h"

/* Read the world file and set the robots, their firmware, the duration and
 * the channel from it (the command line's --time, --ir-range, --ir-loss and
 * --clock-spread win); -1 after a message. */
int world_options_check(options *o);
/* The sd of an analog reading's noise, ADC counts, and robot index's own
 * sequence's seed. */
#define WORLD_ANALOG_NOISE_COUNTS 1.0
uint64_t world_robot_noise_seed(int index);
/* Robot index's uid and EEPROM calibration (-1: erased). */
void world_robot_identity(int index, int *uid, int calibration[4]);
/* The world file and robot index's group in its robots[], for messages
 * (NULL: no world). */
const char *world_robot_group(int index, int *group);
/* The bytes the world's "eeprom" gives, as write(ctx, ...) calls: after
 * kilobot_eeprom_fill, the same for every robot. */
void world_eeprom_fill(eeprom_write_fn write, void *ctx);
/* What the world needs of the robots, whichever simulator runs them (the
 * exact mode's world_avr.c, the native mode's native/native_world.c). */
typedef struct world_robots {
    void (*led)(int index, uint8_t rgb[3]);    /* what its LED shows now, 0..3 each */
    void (*light)(int index, int millivolts);  /* its light sensor's input changed */
    void (*place)(ir_distance_fn distance, void *ctx); /* they moved: the IR channel follows */
    int (*links)(int sender, int *receivers, int room); /* whom sender reaches now */
    void (*ir)(int index, output_ir *out);              /* its IR counts so far, for ir.csv */
} world_robots;
/* The robots are loaded: place them on the IR channel, open the outputs;
 * -1 after a message. physics_thread: step the physics on a thread of its
 * own (world_stepper.h: the same results either way). */
int world_run_start(int n, const options *o, const world_robots *robots, uint32_t nominal_hz,
                    int physics_thread);
/* Where robot index is now (as the robots see it: world_run.c). */
void world_run_position(int index, double *x_mm, double *y_mm);
/* Robot index set its motors' duties at time t (s). */
void world_run_motors(int index, uint8_t left, uint8_t right, double t);
/* After the lockstep window ending at cycle end of the nominal clock:
 * step the physics when a step is due. */
void world_run_after_window(avr_cycle_count_t end, uint32_t nominal_hz);
/* The world holds e-pucks, whose controllers are host processes
 * (world/epuck_run.h), not AVR firmware. */
int world_run_is_epuck(void);
/* The world asks for the native mode ("fidelity": "native"). */
int world_run_is_native(void);
/* Run those; the exit status. */
int world_run_epucks(const options *o);
/* The last sample, the outputs closed; -1 if writing them failed. */
int world_run_finish(void);

#endif
