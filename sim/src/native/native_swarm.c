/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The native mode's robots, window by window (native_swarm.h).
 *
 * A copy of the shared object has one RAM image at one address: running a
 * robot means copying its image in (unless it is the one loaded), and
 * copying the one that was loaded out first. A saved image is summed, and
 * the sum checked when it comes back: whatever wrote into a robot's RAM
 * while it was not running - another robot's stray pointer - is found and
 * reported, never silently run. Stacks sit apart from images, with guard
 * pages between robots. A robot asleep past the window's end, with no
 * frame arriving before it, is not run at all: each robot's next wake is
 * kept in one small array, so a sleeping swarm costs a comparison per
 * robot per window, and the next robot that runs is known ahead. */
#include "native/native_swarm.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#include "native/native_askers.h"
#include "native/native_image_copy.h"
#include "window_workers.h"

/* A window of a sleeping swarm is little work: two threads only pay
 * their waiting for each other below thousands of robots (measured,
 * docs/benchmarks.md "Native mode"). --threads still chooses. */
#define ROBOTS_PER_THREAD 2500

static native_copy *copies;  /* app a's copy on thread t: copies[a * n_threads + t] */
static int n_threads;
static int *app_of;          /* each robot's app (NULL: one app) */
static native_robot *robots;
static int n_robots;
static int *loaded;           /* per copy: whose image it holds (-1: the pristine one) */
static uint64_t window_end;   /* nominal cycles */
static uint32_t nominal;
/* When each robot runs next: in the first window whose end (its own
 * cycles) reaches wake (UINT64_MAX: it has stopped); and where its stack
 * resumes, fetched ahead of it. */
typedef struct wake_time {
    uint64_t wake;
    const char *resume_sp;
    uint32_t hz;
} wake_time;
static wake_time *schedule;
static int *running;          /* per thread: its robots that have not stopped */
/* The robots that ran in a window (the only ones whose logs hold
 * anything): each thread notes its own, once each. */
typedef struct index_list {
    int *index;
    unsigned n, room;
} index_list;
static index_list *ran, ran_all;
static unsigned *taken; /* merging them: how far into each */
static uint8_t *has_run;
static uint8_t *powered_off; /* --faults brownout: not run, deaf, until restarted */

native_robot *native_swarm_robot(int index) { return &robots[index]; }

/* Robot index runs on thread index % n_threads, in its app's copy there. */
static int copy_index(int index) { return (app_of != NULL ? app_of[index] * n_threads : 0) + index % n_threads; }

const native_copy *native_swarm_copy_of(int index) { return &copies[copy_index(index)]; }

const void *native_swarm_robot_memory(int index, const void *address, size_t n) {
    int t = copy_index(index);
    const native_copy *c = &copies[t];
    const native_robot *r = &robots[index];
    const uint8_t *at = address;
    if (at >= r->memory && at + n <= r->memory + r->memory_bytes) return address; /* its stacks */
    if (at < c->image || at + n > c->image + c->image_bytes) return NULL;
    /* robot index's RAM is in its copy while loaded, else in its saved image */
    return (loaded[t] == index ? c->image : r->image) + (at - c->image);
}

const void *native_swarm_robot_stats(int index) {
    const void *at = copies[copy_index(index)].entry.kernel_stats;
    return at != NULL ? native_swarm_robot_memory(index, at, 1) : NULL;
}

static void save(native_robot *r, const native_copy *c) {
    r->image_sum = native_image_copy_summed(r->image, c->image, c->image_bytes);
}

static void restore(native_robot *r, native_copy *c) {
    if (native_image_copy_summed(c->image, r->image, c->image_bytes) != r->image_sum) r->image_changed = 1;
}

/* Robot i's image into its copy, the one there saved first. */
static native_copy *load(int i) {
    int t = copy_index(i);
    native_copy *c = &copies[t];
    if (loaded[t] == i) return c;
    if (loaded[t] >= 0) save(&robots[loaded[t]], c);
    restore(&robots[i], c);
    loaded[t] = i;
    return c;
}

static void *grow(void *p, unsigned *room, unsigned need, size_t size) {
    if (need <= *room) return p;
    unsigned r = *room ? *room : 16;
    while (r < need) r *= 2;
    void *q = realloc(p, (size_t)r * size);
    if (q == NULL) {
        fprintf(stderr, "openswarm-sim: out of memory for a robot's log\n");
        exit(EXIT_FAILURE);
    }
    *room = r;
    return q;
}

#define APPEND(log, list, n, room, from, count)                                        \
    do {                                                                                \
        (log)->list = grow((log)->list, &(log)->room, (log)->n + (count), sizeof *(from)); \
        memcpy((log)->list + (log)->n, (from), (size_t)(count) * sizeof *(from));       \
        (log)->n += (count);                                                            \
    } while (0)

/* The robot's outbound lists into its log, emptied. */
static void take_outbound(native_robot *r) {
    native_io *io = r->io;
    native_log *log = &r->log;
    APPEND(log, sent, n_sent, sent_room, io->sent, io->n_sent);
    APPEND(log, motors, n_motors, motors_room, io->motors, io->n_motors);
    APPEND(log, faults, n_faults, faults_room, io->faults, io->n_faults);
    if (io->console_len != 0) {
        unsigned room = (unsigned)log->console_room;
        log->console = grow(log->console, &room, (unsigned)(log->console_len + io->console_len), 1);
        log->console_room = room;
        memcpy(log->console + log->console_len, io->console, io->console_len);
        log->console_len += io->console_len;
    }
    io->n_sent = io->n_motors = io->n_faults = 0;
    io->console_len = 0;
}

void native_log_clear(native_log *log) {
    log->n_sent = log->n_motors = log->n_faults = 0;
    log->console_len = 0;
}

static void boot(native_robot *r, native_copy *c, uint64_t now) {
    memcpy(c->image, c->pristine, c->image_bytes);
    c->entry.boot(r->io, r->main_stack, c->entry.main_stack_bytes, r->pool, now);
}

/* The first end of a window a robot runs in: one past its clock (a robot
 * that spends time with interrupts masked, receiving or sending a frame,
 * runs on past the window's end, as nothing reaches it until then); if it
 * is asleep, not before it wakes or its next frame's first pulse. */
static uint64_t wake_of(const native_io *io) {
    if (io->state != NATIVE_RUNNING) return UINT64_MAX;
    uint64_t w = io->asleep_until;
    if (w != 0 && io->inbox_count != 0 && io->inbox[io->inbox_head].start < w) w = io->inbox[io->inbox_head].start;
    if (io->board_inputs) w = 0; /* its board's interrupt: at once */
    return w > io->now + 1 ? w : io->now + 1;
}

void native_swarm_woken(int index) {
    if (!powered_off[index]) schedule[index].wake = wake_of(robots[index].io);
}

int native_swarm_powered(int index) { return !powered_off[index]; }

/* Frames that began before cycle at (the robot's own) are lost: it was
 * not listening, or not the program it was listening for. */
static void drop_frames_before(native_io *io, uint64_t at) {
    while (io->inbox_count != 0 && io->inbox[io->inbox_head].start < at) {
        io->inbox_head = (io->inbox_head + 1u) % NATIVE_INBOX_ROOM;
        io->inbox_count--;
    }
}

void native_swarm_power_off(int index) {
    native_io *io = robots[index].io;
    powered_off[index] = 1;
    schedule[index].wake = UINT64_MAX;
    drop_frames_before(io, UINT64_MAX);
    io->led = 0;
}

void native_swarm_restart(int index, uint64_t now) {
    native_robot *r = &robots[index];
    native_io *io = r->io;
    if (io->now > now) now = io->now; /* it ran on past the window's end, frames masked */
    powered_off[index] = 0;
    drop_frames_before(io, now);
    boot(r, load(index), now);
    io->now = now;
    io->asleep_until = 0;
    io->transmit = NATIVE_TRANSMIT_NONE;
    io->led = 0;
    schedule[index].wake = wake_of(io);
    schedule[index].resume_sp = NULL;
}

/* The robots waiting for carrier sense: each thread notes its own as they
 * ask (asking[t]), the main thread the ones it runs on (asking[0]). */
static index_list *asking;

static void note(index_list *l, int i) {
    l->index = grow(l->index, &l->room, l->n + 1, sizeof *l->index);
    l->index[l->n++] = i;
}

static void run_robot(int t, int i, uint64_t own_end) {
    native_robot *r = &robots[i];
    native_copy *c = load(i);
    if (!has_run[i]) {
        has_run[i] = 1;
        note(&ran[t], i);
    }
    for (;;) {
        c->entry.run(own_end);
        take_outbound(r);
        if (r->io->state == NATIVE_RESTART) {
            boot(r, c, r->io->now);
            continue;
        }
        if (r->io->transmit == NATIVE_TRANSMIT_ASKED) {
            note(&asking[t], i);
            break;
        }
        if (r->io->state != NATIVE_RUNNING || r->io->now >= own_end || r->io->asleep_until != 0) break;
    }
    schedule[i].wake = wake_of(r->io);
    schedule[i].resume_sp = r->io->resume_sp;
    if (r->io->state != NATIVE_RUNNING) running[i % n_threads]--;
}

static uint64_t own_end_of(uint32_t hz) { return hz == nominal ? window_end : window_end * hz / nominal; }

static int due(int i) { return schedule[i].wake <= own_end_of(schedule[i].hz); }

/* Thread t's first robot from i on that runs in this window; n_robots:
 * none. */
static int next_due(int i) {
    while (i < n_robots && !due(i)) i += n_threads;
    return i;
}

/* How deep into its stack a robot's resumption reads: the switch frame
 * and the frames of the calls that yielded. */
#define RESUME_BYTES 512

/* A swarm's images and stacks are beyond the caches: the image of the
 * robot that runs next, the top of the stack it resumes on and the state
 * it starts from are fetched while the one before it runs. */
static void prefetch(int i, size_t image_bytes) {
    const native_robot *r = &robots[i];
    for (size_t at = 0; at < image_bytes; at += 64) __builtin_prefetch(r->image + at);
    const char *sp = schedule[i].resume_sp;
    for (size_t at = 0; sp != NULL && at < RESUME_BYTES; at += 64) __builtin_prefetch(sp + at);
    __builtin_prefetch(&r->io->inbox_count);
}

static int run_share(int t) {
    int all_stopped = running[t] == 0; /* as the window began */
    for (int i = next_due(t); i < n_robots;) {
        int after = next_due(i + n_threads);
        if (after < n_robots) prefetch(after, copies[copy_index(after)].image_bytes);
        run_robot(t, i, own_end_of(schedule[i].hz));
        i = after;
    }
    return all_stopped;
}

static size_t page_round(size_t n) {
    size_t page = (size_t)sysconf(_SC_PAGESIZE);
    return (n + page - 1) / page * page;
}

/* n items of size bytes each, cache-line apart, in memory the kernel may
 * back with huge pages: a robot's run touches its image and its native_io,
 * and a thousand robots' small pages are more than the TLB holds (measured:
 * the misses cost as much as copying the images). */
static void *arena(size_t n, size_t size, size_t *stride) {
    *stride = (size + 63) / 64 * 64;
    size_t bytes = page_round(n * *stride);
    void *p = mmap(NULL, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
    if (p == MAP_FAILED) return NULL;
    madvise(p, bytes, MADV_HUGEPAGE); /* a hint: without it, small pages */
    return p;
}

/* [guard][pool][guard][main stack]: an overflow of either faults. */
static int allocate_stacks(native_robot *r, const native_entry *e) {
    size_t page = (size_t)sysconf(_SC_PAGESIZE), pool = page_round(e->stack_pool_bytes);
    size_t main_stack = page_round(e->main_stack_bytes);
    r->memory_bytes = page + pool + page + main_stack;
    r->memory = mmap(NULL, r->memory_bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
    if (r->memory == MAP_FAILED) return -1;
    r->pool = r->memory + page;
    r->main_stack = r->pool + pool + page;
    if (mprotect(r->memory, page, PROT_NONE) != 0 || mprotect(r->pool + pool, page, PROT_NONE) != 0) return -1;
    return 0;
}

/* The largest image of the apps': every robot's saved image gets its room. */
static size_t largest_image(int n_copies) {
    size_t bytes = 0;
    for (int k = 0; k < n_copies; k++) bytes = copies[k].image_bytes > bytes ? copies[k].image_bytes : bytes;
    return bytes;
}

int native_swarm_create(native_copy *all_copies, int n_apps, int n_copies, const int *apps, int n) {
    copies = all_copies;
    n_threads = n_copies;
    n_robots = n;
    app_of = n_apps > 1 ? malloc((size_t)n * sizeof *app_of) : NULL;
    if (app_of != NULL) memcpy(app_of, apps, (size_t)n * sizeof *app_of);
    robots = calloc((size_t)n, sizeof *robots);
    schedule = calloc((size_t)n, sizeof *schedule);
    loaded = malloc((size_t)(n_apps * n_copies) * sizeof *loaded);
    running = calloc((size_t)n_copies, sizeof *running);
    asking = calloc((size_t)n_copies, sizeof *asking);
    ran = calloc((size_t)n_copies, sizeof *ran);
    taken = calloc((size_t)n_copies, sizeof *taken);
    has_run = calloc((size_t)n, 1);
    powered_off = calloc((size_t)n, 1);
    if (powered_off == NULL || robots == NULL || schedule == NULL || loaded == NULL || running == NULL ||
        asking == NULL || ran == NULL || taken == NULL || has_run == NULL || (n_apps > 1 && app_of == NULL))
        return -1;
    for (int k = 0; k < n_apps * n_copies; k++) loaded[k] = -1;
    size_t io_stride, image_stride;
    uint8_t *ios = arena((size_t)n, sizeof(native_io), &io_stride);
    uint8_t *images = arena((size_t)n, largest_image(n_apps * n_copies), &image_stride);
    if (ios == NULL || images == NULL) return -1;
    for (int i = 0; i < n; i++) {
        native_robot *r = &robots[i];
        const native_copy *c = &copies[copy_index(i)];
        r->io = (native_io *)(ios + (size_t)i * io_stride); /* zeroed, as mapped */
        r->image = images + (size_t)i * image_stride;
        if (allocate_stacks(r, &c->entry) != 0) {
            fprintf(stderr, "openswarm-sim: out of memory for native robot %d of %d\n", i, n);
            return -1;
        }
    }
    return 0;
}

void native_swarm_boot(void) {
    for (int i = 0; i < n_robots; i++) {
        native_copy *c = &copies[copy_index(i)];
        boot(&robots[i], c, 0);
        save(&robots[i], c);
        schedule[i] = (wake_time){wake_of(robots[i].io), NULL, robots[i].hz};
        running[i % n_threads]++;
    }
    window_workers_begin(n_threads, run_share);
}

/* The robots the threads noted asking, onto the askers' heap (by when
 * they asked in the nominal clock). */
static void gather_askers(void) {
    for (int t = 0; t < n_threads; t++) {
        for (unsigned k = 0; k < asking[t].n; k++) {
            int i = asking[t].index[k];
            native_askers_push(robots[i].io->now * nominal / robots[i].hz, i);
        }
        asking[t].n = 0;
    }
}

/* Every robot runs to the window's end on its thread, or until it asks
 * to transmit. The askers are then answered in the order they asked, each
 * run on (alone) until the end or its next question: whoever began a
 * frame before a robot looks is heard, whatever thread ran it. */
int native_swarm_window(uint64_t end, uint32_t nominal_hz, native_carrier_fn clear) {
    window_end = end;
    nominal = nominal_hz;
    int all_stopped = window_workers_run();
    gather_askers();
    for (int i; (i = native_askers_pop()) >= 0;) {
        native_robot *r = &robots[i];
        const native_sent *frame = &r->log.sent[r->log.n_sent - 1];
        if (clear(i, frame->at)) {
            r->io->transmit = NATIVE_TRANSMIT_CLEAR;
        } else {
            r->io->transmit = NATIVE_TRANSMIT_BUSY;
            r->log.n_sent--; /* it never went out */
        }
        run_robot(0, i, own_end_of(r->hz));
        gather_askers(); /* it, if it asks again */
    }
    return all_stopped;
}

/* Each thread's list is in index order (a robot that asked to transmit
 * runs again after the others, but was noted as it first ran): merged. */
const int *native_swarm_ran(unsigned *n) {
    ran_all.n = 0;
    for (int t = 0; t < n_threads; t++) taken[t] = 0;
    for (;;) {
        int from = -1;
        for (int t = 0; t < n_threads; t++)
            if (taken[t] < ran[t].n && (from < 0 || ran[t].index[taken[t]] < ran[from].index[taken[from]]))
                from = t;
        if (from < 0) break;
        int i = ran[from].index[taken[from]++];
        has_run[i] = 0;
        note(&ran_all, i);
    }
    for (int t = 0; t < n_threads; t++) ran[t].n = 0;
    *n = ran_all.n;
    return ran_all.index;
}

void native_swarm_end(void) { window_workers_end(); }

int native_swarm_threads_for(int requested, int n) {
    return window_workers_count(requested, n, ROBOTS_PER_THREAD);
}
