/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The overhead controller natively (native_ohc.h). A message is handed
 * over the window before its first pulse: a frame handed over must start
 * in its receivers' future, and a robot runs to the window's end before
 * it is told anything. Its distance readings are zero: the controller is
 * above the robots, no robot of the swarm (the exact mode's receivers read
 * whatever their sensors last held). */
#include "native/native_ohc.h"

#include <string.h>

#include "native/native_air.h"
#include "native/native_swarm.h"

/* --ohc's messages, in time order (options keep them as given). */
static ohc_message messages[MAX_OHC_MESSAGES];
static int n_messages, next_message, n_robots;
static uint32_t nominal;

void native_ohc_start(const options *o, int n, uint32_t nominal_hz) {
    n_messages = o->n_ohc;
    memcpy(messages, o->ohc, (size_t)n_messages * sizeof *messages);
    for (int i = 1; i < n_messages; i++) /* insertion: stable, and 16 at most */
        for (int k = i; k > 0 && messages[k].seconds < messages[k - 1].seconds; k--) {
            ohc_message m = messages[k];
            messages[k] = messages[k - 1];
            messages[k - 1] = m;
        }
    next_message = 0;
    n_robots = n;
    nominal = nominal_hz;
}

/* The exact mode's first flash: one cycle past the message's time, on the
 * robot's own clock. */
static uint64_t first_pulse(double seconds, uint32_t hz) { return (uint64_t)(seconds * hz) + 1; }

void native_ohc_deliver(uint64_t until) {
    for (; next_message < n_messages && first_pulse(messages[next_message].seconds, nominal) < until; next_message++) {
        native_frame f;
        memset(&f, 0, sizeof f);
        ohc_frame(&messages[next_message], f.bytes);
        for (int i = 0; i < n_robots; i++) {
            uint32_t hz = native_swarm_robot(i)->hz;
            f.start = first_pulse(messages[next_message].seconds, hz);
            f.end = f.start + (uint64_t)IR_FRAME_SLOTS * IR_BIT_CYCLES;
            native_air_hand_over(i, &f);
        }
    }
}
