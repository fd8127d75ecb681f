/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The end of every run: what the firmware lost or refused without failing,
 * as warnings with the fix. The kernel counts every refusal (os_stats,
 * openswarm/fault.h), but a firmware rarely checks the status it gets back:
 * a handler subscribed to an event nobody registered never runs, and the run
 * looked fine. Faults are not repeated here: the console reported them as
 * they happened, and they fail the run already. */
#include <string.h>

#include "sim.h"
#include "kernel_losses.h"

#define KERNEL_BYTES (2 * OS_STATS_COUNTERS + 1) /* and the queue's peak byte */

int kernel_loss_warnings(int robot_index, robot_kind kind, const uint16_t *counters) {
    int warnings = 0;
    for (size_t i = 0; i < KERNEL_LOSSES; i++) {
        const kernel_loss *l = &kernel_losses[i];
        unsigned n = counters[l->index];
        if (n == 0) continue;
        warning_note(robot_index, "%u %s%s; %s%s", n, l->what, l->what_on[kind], l->fix, l->fix_on[kind]);
        warnings++;
    }
    return warnings;
}

/* The robot's index for the warnings, or -1 when it runs alone. */
static int robot_named(const robot *r) {
    return r->console.prefix[0] != '\0' ? r->index : -1;
}

static int kernel_warnings(const robot *r) {
    const struct counter_symbols *s = &r->counters;
    if (s->kernel == 0 || s->kernel_size != KERNEL_BYTES || s->kernel + KERNEL_BYTES > r->avr->ramend + 1u)
        return 0; /* no kernel (a plain AVR program), or one this simulator does not know */
    uint16_t counters[OS_STATS_COUNTERS];
    for (unsigned i = 0; i < OS_STATS_COUNTERS; i++) {
        uint32_t at = r->counters.kernel + 2u * i;
        counters[i] = (uint16_t)(r->avr->data[at] | r->avr->data[at + 1] << 8);
    }
    return kernel_loss_warnings(robot_named(r), ROBOT_KILOBOT, counters);
}

static int console_warnings(const robot *r) {
    const console *c[] = {&r->console, &r->serial};
    int warnings = 0;
    for (int i = 0; i < 2; i++) {
        if (c[i]->from_interrupt == 0) continue;
        warning_note(robot_named(r), "%u character(s) printed from an interrupt (the first at %.6f s): "
                     "they cut into the lines threads print; print from a thread or an event handler "
                     "(send an event from the interrupt, print in its handler)",
                     c[i]->from_interrupt, c[i]->from_interrupt_at);
        warnings++;
    }
    return warnings;
}

int warnings_fail_run(int warnings, const options *o) {
    if (warnings == 0 || !o->strict) return 0;
    fprintf(stderr, "openswarm-sim: %d warning%s (above) and --strict: the run fails\n", warnings,
            warnings == 1 ? "" : "s");
    return 1;
}

int firmware_warnings_report(const robot *r) {
    return kernel_warnings(r) + handler_watch_report(r, robot_named(r)) + console_warnings(r);
}
