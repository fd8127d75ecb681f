/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The end of every run: what the firmware lost or refused without failing,
 * as warnings with the fix. The kernel counts every refusal (os_stats,
 * openswarm/fault.h), but a firmware rarely checks the status it gets back:
 * a handler subscribed to an event nobody registered never runs, and the run
 * looked fine. Faults are not repeated here: the console reported them as
 * they happened, and they fail the run already. */
#include <string.h>

#include "sim.h"

/* os_stats' counters this reports, by their index in sys_stats, with what
 * a non-zero count means and what to do. */
typedef struct loss {
    unsigned index;
    const char *what;
    const char *fix;
} loss;

static const loss losses[] = {
    {0, "thread start(s) refused: no free thread slot",
     "raise \"max_threads\" in openswarm.json's \"kernel\", or declare the threads in its \"threads\""},
    {1, "thread start(s) refused: no room for a stack",
     "raise \"stack_pool\" in openswarm.json's \"kernel\", or give the threads smaller \"stack\"s"},
    {2, "event registration(s) refused: no room for the event's data, its handlers never run "
        "(a kilolib program's pool holds kilolib's own: kilobot_sensors_init() needs 6 bytes more)",
     "declare the app's events in openswarm.json's \"events\" (the pool is sized for them) or "
     "raise \"event_data\" in its \"kernel\""},
    {3, "subscription(s) refused: every subscription slot in use, those handlers never run",
     "raise \"max_subscriptions\" in openswarm.json's \"kernel\""},
    {4, "event send(s) refused: the event queue was full, those occurrences are lost",
     "raise \"event_queue\" in openswarm.json's \"kernel\", or send less often"},
    {5, "device registration(s) refused: no free device slot (a kilolib program gets kilolib's "
        "own few, kilobot_sensors_init() needs 3 more)",
     "raise \"max_devices\" in openswarm.json's \"kernel\""},
    {6, "queued event(s) discarded: their event was unregistered before they were dispatched",
     "unregister an event only once its last occurrence is handled"},
    {11, "subscription(s) refused: the event was not registered, the handler never runs (a "
         "device's event, e.g. KILOBOT_EVENT_LIGHT, is registered by its init)",
     "register the event before subscribing to it: call kilobot_sensors_init() (or "
     "Sys_Register_Event) first"},
};

#define KERNEL_BYTES (2 * OS_STATS_COUNTERS + 1) /* and the queue's peak byte */

int kernel_loss_warnings(const char *prefix, const uint16_t *counters) {
    int warnings = 0;
    for (size_t i = 0; i < sizeof losses / sizeof losses[0]; i++) {
        unsigned n = counters[losses[i].index];
        if (n == 0) continue;
        fprintf(stderr, "openswarm-sim: %swarning: %u %s; %s\n", prefix, n, losses[i].what, losses[i].fix);
        warnings++;
    }
    return warnings;
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
    return kernel_loss_warnings(r->console.prefix, counters);
}

static int console_warnings(const robot *r) {
    const console *c[] = {&r->console, &r->serial};
    int warnings = 0;
    for (int i = 0; i < 2; i++) {
        if (c[i]->from_interrupt == 0) continue;
        fprintf(stderr, "openswarm-sim: %swarning: %u character(s) printed from an interrupt "
                        "(the first at %.6f s): they cut into the lines threads print; print from a "
                        "thread or an event handler (send an event from the interrupt, print in "
                        "its handler)\n",
                r->console.prefix, c[i]->from_interrupt, c[i]->from_interrupt_at);
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
    return kernel_warnings(r) + handler_watch_report(r) + console_warnings(r);
}
