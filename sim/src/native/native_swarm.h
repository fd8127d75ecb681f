/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The native mode's robots (ports/native): each its own RAM image, stacks
 * and native_io, run window by window on one thread or several. Thread t
 * runs robots t, t + T, ... in its own copy of the shared object (a copy's
 * image address is fixed, so a robot stays with its copy; a world of
 * several apps loads each app once per thread). Within a window
 * robots see nothing of each other: what one sends is handed over after
 * it (native_air.c), so the run is the same on any number of threads. */
#ifndef OPENSWARM_NATIVE_SWARM_H
#define OPENSWARM_NATIVE_SWARM_H

#include <stddef.h>
#include <stdint.h>

#include "native/native_load.h"

/* What a robot did in the window, for the main thread to act on in robot
 * order (the robot's own lists in native_io are small: they are moved
 * here whenever it yields). */
typedef struct native_log {
    native_sent *sent;
    unsigned n_sent, sent_room;
    native_motor_change *motors;
    unsigned n_motors, motors_room;
    native_fault *faults;
    unsigned n_faults, faults_room;
    char *console;
    size_t console_len, console_room;
} native_log;

typedef struct native_robot {
    native_io *io;
    uint32_t hz;          /* its own clock (--clock-spread) */
    uint8_t *image;       /* its RAM while another robot's is loaded */
    uint64_t image_sum;   /* what image summed to when it was saved */
    int image_changed;    /* it changed meanwhile: a stray write (reported) */
    uint8_t *memory;      /* its stacks: pool and main's, guard pages around */
    size_t memory_bytes;
    uint8_t *pool, *main_stack;
    native_log log;
} native_robot;

/* The threads for n robots (requested: --threads, 0 picks by the machine):
 * load that many copies. */
int native_swarm_threads_for(int requested, int n);
/* Robots n of the loaded copies, each with a fresh native_io (zeroed; the
 * caller fills it before they boot). copies holds n_apps apps' copies, one
 * per thread each (app a's on thread t at a * threads + t); robot i runs
 * app apps[i] (apps may be NULL for one app). -1 after a message. */
int native_swarm_create(native_copy *copies, int n_apps, int threads, const int *apps, int n);
native_robot *native_swarm_robot(int index);
/* Where robot index's kernel counters (sys_stats) are now, in its copy or
 * its saved image; NULL if its image has none. */
const void *native_swarm_robot_stats(int index);
/* The copy of the shared object robot index runs in. */
const native_copy *native_swarm_copy_of(int index);
/* Where robot index's n bytes at address (as its code sees them: in its
 * copy's RAM image, or its stacks) are now; NULL for anywhere else. */
const void *native_swarm_robot_memory(int index, const void *address, size_t n);
/* Power every robot up (after their native_io is filled), and start the
 * threads. */
void native_swarm_boot(void);
/* Carrier sense for robot index at its own cycle at: 1 when the channel
 * is clear (the frame is then on the air from at). */
typedef int (*native_carrier_fn)(int index, uint64_t at);
/* Every robot up to cycle end of the nominal clock (hz), transmissions
 * cleared or refused by clear in the order asked: 1 when every robot has
 * stopped. */
int native_swarm_window(uint64_t end, uint32_t nominal_hz, native_carrier_fn clear);
void native_swarm_end(void);
/* The robots that ran in the last window, in index order, n of them: the
 * only ones whose logs hold anything. Then none, until the next window. */
const int *native_swarm_ran(unsigned *n);
/* Robot index's inbox changed between windows: it may run sooner. */
void native_swarm_woken(int index);
/* Between windows (--faults): robot index starts again from reset at its
 * own cycle now, or later if its clock is past it - its RAM as loaded (the
 * start-up code sets .data and .bss again), its LED dark, the frames that
 * began before lost - as kilobot_restart's NATIVE_RESTART does; or it
 * loses its power: it neither runs nor hears until restarted. */
void native_swarm_restart(int index, uint64_t now);
void native_swarm_power_off(int index);
/* Robot index hears frames: not powered off. */
int native_swarm_powered(int index);
/* The log emptied (its room kept). */
void native_log_clear(native_log *log);

#endif
