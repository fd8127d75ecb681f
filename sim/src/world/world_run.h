/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* A run in a world (--world FILE): what the file sets of the options, the
 * robots' bodies moving with their motors, the IR channel and the light
 * sensors following them, and the outputs sampled as it goes. */
#ifndef OPENSWARM_WORLD_RUN_H
#define OPENSWARM_WORLD_RUN_H

#include "sim.h"

/* Read the world file and set the robots, their firmware, the duration and
 * the channel from it (the command line's --time, --ir-range, --ir-loss and
 * --clock-spread win); -1 after a message. */
int world_options_check(options *o);
/* Robot index's analog inputs carry its own noise (before they are set). */
void world_robot_noise(robot *r, int index);
/* Robot index's uid and EEPROM calibration (-1: erased). */
void world_robot_identity(int index, int *uid, int calibration[4]);
/* The robots are loaded: follow their motors, place them on the IR
 * channel, open the outputs; -1 after a message. */
int world_run_start(robot *robots, int n, const options *o, uint32_t nominal_hz);
/* After the lockstep window ending at cycle end of the nominal clock:
 * step the physics when a step is due. */
void world_run_after_window(avr_cycle_count_t end, uint32_t nominal_hz);
/* The world holds e-pucks, whose controllers are host processes
 * (world/epuck_run.h), not AVR firmware. */
int world_run_is_epuck(void);
/* Run those; the exit status. */
int world_run_epucks(const options *o);
/* The last sample, the outputs closed; -1 if writing them failed. */
int world_run_finish(void);

#endif
