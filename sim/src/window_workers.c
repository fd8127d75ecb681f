/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The threads that share each window (window_workers.h). A window is a
 * few microseconds of work: a thread waiting for the others spins on a
 * counter a little while first, then sleeps on it (a futex), so threads
 * sharing their cores with other work do not burn them: spinning alone
 * made two threads slower than one on a busy machine. */
#include "window_workers.h"

#include <limits.h>
#include <linux/futex.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/syscall.h>
#include <unistd.h>

#include "sim.h"

#define SPINS_BEFORE_SLEEP 500

static window_share_fn run_share; /* each window's */
static window_share_fn job;       /* this round's: run_share, or another job */
static int n_threads = 1;
static pthread_t *workers;
static atomic_uint generation; /* a new window; the workers start it */
static atomic_int pending;     /* workers still in the window */
static atomic_int any_running; /* a share has not stopped */
static atomic_int stopping;
static atomic_int workers_asleep; /* on generation */
static atomic_int main_asleep;    /* on pending */

static void futex_wait(void *word, int value) {
    syscall(SYS_futex, word, FUTEX_WAIT_PRIVATE, value, NULL, NULL, 0);
}

static void futex_wake(void *word) { syscall(SYS_futex, word, FUTEX_WAKE_PRIVATE, INT_MAX, NULL, NULL, 0); }

static void spin_once(void) {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
}

/* Until the main thread starts a new window (or stops). */
static unsigned wait_for_window(unsigned seen) {
    unsigned now;
    for (int spins = 0; (now = atomic_load(&generation)) == seen; spins++) {
        if (spins < SPINS_BEFORE_SLEEP) {
            spin_once();
            continue;
        }
        atomic_fetch_add(&workers_asleep, 1);
        if (atomic_load(&generation) == seen) futex_wait(&generation, (int)seen);
        atomic_fetch_sub(&workers_asleep, 1);
        spins = 0;
    }
    return now;
}

static void *worker(void *arg) {
    int t = (int)(intptr_t)arg;
    unsigned seen = 0;
    for (;;) {
        seen = wait_for_window(seen);
        if (atomic_load(&stopping)) return NULL;
        if (!job(t)) atomic_store_explicit(&any_running, 1, memory_order_relaxed);
        if (atomic_fetch_sub(&pending, 1) == 1 && atomic_load(&main_asleep)) futex_wake(&pending);
    }
}

/* Until every worker has finished the window. */
static void wait_for_workers(void) {
    int left;
    for (int spins = 0; (left = atomic_load(&pending)) != 0; spins++) {
        if (spins < SPINS_BEFORE_SLEEP) {
            spin_once();
            continue;
        }
        atomic_store(&main_asleep, 1);
        if ((left = atomic_load(&pending)) != 0) futex_wait(&pending, left);
        atomic_store(&main_asleep, 0);
        spins = 0;
    }
}

static void start_window(void) {
    atomic_fetch_add(&generation, 1);
    if (atomic_load(&workers_asleep) > 0) futex_wake(&generation);
}

int window_workers_count(int requested, int n, int per_thread) {
    if (n < 2) return 1;
    if (requested > 0) return requested < n ? requested : n;
    long cores = sysconf(_SC_NPROCESSORS_ONLN);
    int by_items = n / per_thread;
    int t = cores < by_items ? (int)cores : by_items;
    return t > 1 ? t : 1;
}

void window_workers_begin(int threads, window_share_fn share) {
    run_share = share;
    n_threads = threads;
    atomic_store(&stopping, 0);
    if (n_threads == 1) return;
    workers = calloc((size_t)n_threads, sizeof *workers);
    for (int t = 1; workers != NULL && t < n_threads; t++) {
        if (pthread_create(&workers[t], NULL, worker, (void *)(intptr_t)t) != 0) {
            fprintf(stderr, "openswarm-sim: cannot start thread %d of %d; give --threads 1\n", t,
                    n_threads);
            exit(EXIT_CRASH);
        }
    }
}

int window_workers_run(void) { return window_workers_run_job(run_share); }

/* job is written before the generation moves on, and read by the workers
 * after they see it move: the atomic orders them. */
int window_workers_run_job(window_share_fn each) {
    if (n_threads == 1) return each(0);
    job = each;
    atomic_store_explicit(&any_running, 0, memory_order_relaxed);
    atomic_store(&pending, n_threads - 1);
    start_window();
    int mine_stopped = each(0);
    wait_for_workers();
    return mine_stopped && !atomic_load_explicit(&any_running, memory_order_relaxed);
}

int window_workers_threads(void) { return n_threads; }

void window_workers_end(void) {
    if (n_threads == 1) return;
    atomic_store(&stopping, 1);
    start_window();
    for (int t = 1; t < n_threads; t++) pthread_join(workers[t], NULL);
    free(workers);
}
