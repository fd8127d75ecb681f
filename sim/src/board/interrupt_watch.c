/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* A firmware that masks interrupts and never unmasks them hangs: no tick,
 * no events, and the kernel's own watch on handlers (which runs from the
 * tick) cannot see it. Every instruction notes the I flag
 * (interrupt_watch_step, sim.h); between lockstep windows a robot whose
 * flag has stayed clear for longer than the limit, while it runs (not
 * asleep, not stopped by a debugger), is reported once and fails the run.
 * (Sampling the flag only at window ends saw a robot that sleeps between
 * ticks always inside the tick's interrupt, I clear, and called it hung.) */
#include "sim.h"

void interrupt_watch_check(robot *r, double limit_ms) {
    avr_t *avr = r->avr;
    if (limit_ms <= 0 || r->hung || r->state != cpu_Running || r->masked_since == 0) return;
    double masked_ms = 1000.0 * (double)(avr->cycle - r->masked_since) / avr->frequency;
    if (masked_ms <= limit_ms) return;
    r->hung = 1;
    fprintf(stderr, "openswarm-sim: %sinterrupts masked for over %g ms, since %.6f s (PC 0x%04x "
                    "now): the firmware hangs with interrupts off (a cli() or critical section "
                    "that never ends); --mask-limit MS sets the limit, 0 turns it off\n",
            r->console.prefix, limit_ms, (double)r->masked_since / avr->frequency,
            (unsigned)avr->pc);
}
