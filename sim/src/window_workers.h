/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* Threads that share each window of a run: thread t runs its share
 * (share(t)) of every window the main thread starts, the main thread
 * share(0). Both simulators' robots run this way: the exact mode's
 * (lockstep.c) and the native mode's (native/native_swarm.c). */
#ifndef OPENSWARM_WINDOW_WORKERS_H
#define OPENSWARM_WINDOW_WORKERS_H

/* share(t): thread t's part of a window; 1 when everything of it has stopped. */
typedef int (*window_share_fn)(int t);

/* Start threads - 1 workers (none for 1). */
void window_workers_begin(int threads, window_share_fn share);
/* One window, every share run; 1 when every share said it has stopped. */
int window_workers_run(void);
/* Between windows: job(t) on every thread t, as a window's shares run
 * (the same result on any number of threads is job's to keep). */
int window_workers_run_job(window_share_fn job);
/* The threads begun (1: the main thread alone). */
int window_workers_threads(void);
void window_workers_end(void);
/* threads for requested (0: by the machine's cores, at least per_thread
 * items each) and n items. */
int window_workers_count(int requested, int n, int per_thread);

#endif
