/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* Stopping a run on SIGINT or SIGTERM (interrupt.h). The handler only
 * notes the signal: the main loops look at it between windows, where
 * every robot, the physics and the outputs are at one time. */
#include "interrupt.h"

#include <signal.h>
#include <stdio.h>
#include <string.h>

static volatile sig_atomic_t caught;
static double stopped_at_s = -1;

static void on_signal(int signal_number) {
    if (caught == 0) {
        caught = signal_number;
        return;
    }
    if (signal_number == SIGINT) { /* asked twice: the person does not want to wait */
        signal(SIGINT, SIG_DFL);
        raise(SIGINT);
    }
}

void interrupt_catch(void) {
    struct sigaction a;
    memset(&a, 0, sizeof a);
    a.sa_handler = on_signal;
    /* restarted: a write or read the signal lands in must not fail */
    a.sa_flags = SA_RESTART;
    sigemptyset(&a.sa_mask);
    /* Started with SIGINT ignored (a script's background job `sim &`): it
     * stays ignored, so a Ctrl-C meant for the foreground leaves it be. */
    struct sigaction was;
    if (sigaction(SIGINT, NULL, &was) == 0 && was.sa_handler != SIG_IGN) sigaction(SIGINT, &a, NULL);
    sigaction(SIGTERM, &a, NULL);
}

int interrupt_caught(void) { return caught; }

int interrupt_stop_here(double t_s) {
    if (caught == 0) return 0;
    if (stopped_at_s < 0) stopped_at_s = t_s;
    return 1;
}

int interrupt_finish(const char *written) {
    int signal_number = caught;
    const char *name = signal_number == SIGINT ? "SIGINT" : "SIGTERM";
    fprintf(stderr, "openswarm-sim: interrupted by %s at %.3f s of simulated time: %s%s; exit status %d "
                    "(run it again for the whole run)\n",
            name, stopped_at_s < 0 ? 0.0 : stopped_at_s,
            written != NULL && written[0] ? "wrote the run up to then to " : "stopped there, its outputs closed",
            written != NULL ? written : "", 128 + signal_number);
    return 128 + signal_number;
}
