/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* Ctrl-C (SIGINT) and SIGTERM during a run: the run stops at the next
 * safe point of its main loop (between two lockstep windows, two native
 * windows or two e-puck steps), then writes what it simulated so far as
 * it would at the end, and exits with 128 + the signal (130, 143). A
 * second SIGINT while it finishes ends it at once (the outputs written at
 * the end may then be missing, never half: output/part_file.c); a second
 * SIGTERM is ignored: a job scheduler sends one to every process. */
#ifndef OPENSWARM_INTERRUPT_H
#define OPENSWARM_INTERRUPT_H

/* Catch SIGINT and SIGTERM from now on. */
void interrupt_catch(void);
/* The signal caught, or 0. */
int interrupt_caught(void);
/* In a main loop at simulated time t_s: 1 when the run must stop here
 * (t_s is kept for the message). */
int interrupt_stop_here(double t_s);
/* After the outputs were written: one line saying when the run stopped
 * and what it wrote (written: a list of files, or NULL); the exit status
 * 128 + the signal. */
int interrupt_finish(const char *written);

#endif
