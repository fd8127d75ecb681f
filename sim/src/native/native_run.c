/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* A run in the native mode (native_run.h): the robots of a shared object
 * built with `openswarm build --native`, window by window, in a world or
 * placed as the command line says; after each window, in robot order,
 * what they printed, the faults they reported, their motors and their
 * frames. Everything a robot is told, it is told between windows: the
 * same seed gives the same run, on any number of threads. */
#include "native/native_run.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "faults/faults.h"
#include "interrupt.h"
#include "output/output.h"
#include "native/native_air.h"
#include "native/native_apps.h"
#include "native/native_counters.h"
#include "native/native_faults.h"
#include "native/native_handlers.h"
#include "native/native_ohc.h"
#include "native/native_swarm.h"
#include "progress.h"
#include "world/world_run.h"

/* A window: 1 ms of the nominal clock. A frame reaches its receivers one
 * window after it left (native_air.h), and a busy robot is switched in
 * and out once per window. */
#define WINDOW_MS 1.0

static int n_robots;
static uint32_t nominal_hz;
static const options *opts;
/* Each robot's console line so far (printed when it ends). */
typedef struct console_line {
    char text[256];
    size_t len;
} console_line;
static console_line *lines;
static FILE *console_csv; /* --console-csv, written after each window in robot order */
static unsigned faults_reported;
static uint64_t run_end; /* the last window's end, nominal cycles: how long the run was */

/* What the exact mode supports and this one does not (yet): refused by
 * name rather than ignored. */
static int refuse_exact_only(const options *o) {
    static const char *fix = "run it in the exact mode (the firmware's .elf, `openswarm run` without --native)";
    const char *what = o->marks ? "--marks" : o->n_watched ? "--watch-irq" : o->profile ? "--profile"
                     : o->trace ? "--trace" : o->trace_csv ? "--trace-csv" : o->gdb_port ? "--gdb"
                     : o->vcd ? "--vcd" : o->ir_log ? "--ir-log"
                     : o->main_stack ? "--main-stack" : NULL;
    if (what == NULL) return 0;
    fprintf(stderr, "openswarm-sim: %s measures the simulated MCU, which the native mode does not "
                    "simulate: %s\n", what, fix);
    return -1;
}

/* ---- the robots as the world sees them ---- */

static void led(int index, uint8_t rgb[3]) {
    uint8_t c = native_swarm_robot(index)->io->led;
    rgb[0] = c & 3u;
    rgb[1] = (c >> 2) & 3u;
    rgb[2] = (c >> 4) & 3u;
}

static void light(int index, int millivolts) {
    native_swarm_robot(index)->io->adc_mv[NATIVE_ADC_LIGHT] = (uint16_t)millivolts;
}

/* The world's distances, and its robots' positions for the air's grid. */
static double *positions;

static void place(ir_distance_fn distance, void *ctx) {
    for (int i = 0; i < n_robots; i++) world_run_position(i, &positions[2 * i], &positions[2 * i + 1]);
    native_air_place(distance, ctx, positions);
}

static void ir(int index, output_ir *out) {
    out->firmware_known = native_counters_ir(index, out->firmware);
    native_air_counts(index, &out->heard, &out->lost_channel);
}

static const world_robots native_robots = {led, light, place, native_air_links, ir};

/* ---- what each robot is told before it starts ---- */

static void write_eeprom(void *ctx, uint16_t address, const uint8_t *bytes, uint32_t n) {
    native_io *io = ctx;
    for (uint32_t i = 0; i < n; i++) io->eeprom[(address + i) % NATIVE_EEPROM_BYTES] = bytes[i];
}

static int analog_mv(int given, int fallback) { return given >= 0 ? given : fallback; }

static void configure(int index, const options *o) {
    native_robot *r = native_swarm_robot(index);
    native_io *io = r->io;
    int uid = o->uid >= 0 ? o->uid + index : -1, calibration[4];
    memcpy(calibration, o->calibration, sizeof calibration);
    uint64_t seed = 0x5DEECE66Dull * (uint64_t)(index + 1);
    if (o->world != NULL) {
        world_robot_identity(index, &uid, calibration);
        seed = world_robot_noise_seed(index);
    }
    /* robot_clock_error ranks the robot among all: n steps a robot. */
    double spread = o->clock_spread_pct == 0 ? 0 : o->clock_spread_pct / 100.0 * robot_clock_error(index, o->robots);
    /* its drift logged before its blank calibration, as the exact mode does */
    r->hz = faults_clock_rate(index, (uint32_t)lround(nominal_hz * (1.0 + spread)));
    memset(io->eeprom, 0xFF, sizeof io->eeprom);
    kilobot_eeprom_fill(write_eeprom, io, uid, calibration);
    if (o->world != NULL) world_eeprom_fill(write_eeprom, io);
    if (faults_blank_calibration(index)) kilobot_eeprom_erase_calibration(write_eeprom, io);
    io->adc_mv[NATIVE_ADC_LIGHT] = (uint16_t)analog_mv(o->light_mv, 0);
    io->adc_mv[NATIVE_ADC_VOLTAGE] = (uint16_t)analog_mv(o->voltage_mv, 0);
    io->adc_mv[NATIVE_ADC_TEMPERATURE] = (uint16_t)analog_mv(o->temperature_mv, 0);
    io->charging = (uint8_t)o->charging;
    io->noise = seed | 1u;
    io->noise_counts = WORLD_ANALOG_NOISE_COUNTS;
}

/* ---- after each window, in robot order ---- */

static double seconds_of(const native_robot *r, uint64_t cycle) { return (double)cycle / r->hz; }

/* A whole console line: printed unless --quiet, and a row of --console-csv. */
static void emit_line(int index, const char *text, double t) {
    if (console_csv != NULL) console_csv_row(console_csv, t, index, text);
    if (opts->quiet) return;
    char prefix[32] = "";
    if (n_robots > 1) snprintf(prefix, sizeof prefix, "[robot %d] ", index);
    if (opts->timestamps)
        printf("%s[%.6f] %s\n", prefix, t, text);
    else
        printf("%s%s\n", prefix, text);
}

static void print_console(int index, const native_robot *r) {
    console_line *l = &lines[index];
    for (size_t k = 0; k < r->log.console_len; k++) {
        char c = r->log.console[k];
        if (c == '\r') continue;
        if (c != '\n' && l->len < sizeof l->text - 1) {
            l->text[l->len++] = c;
            continue;
        }
        if (c != '\n') continue; /* a line past its room: the rest of it is dropped */
        l->text[l->len] = '\0';
        emit_line(index, l->text, seconds_of(r, r->io->now));
        l->len = 0;
    }
}

static void print_faults(int index, const native_robot *r) {
    for (unsigned k = 0; k < r->log.n_faults; k++) {
        const native_fault *f = &r->log.faults[k];
        const char *name = r->io->thread_name[f->pid % NATIVE_THREAD_NAMES];
        char prefix[32] = "";
        if (n_robots > 1) snprintf(prefix, sizeof prefix, "[robot %d] ", index);
        fprintf(stderr, "openswarm-sim: %skernel fault: %s in thread %u%s%s%s at %.6f s\n", prefix,
                kernel_fault_name(f->fault), f->pid, name[0] ? " (" : "", name, name[0] ? ")" : "",
                seconds_of(r, f->at));
        faults_reported++;
    }
}

static int *senders; /* the window's, in index order */

static void after_window(void) {
    unsigned n_ran, n_senders = 0;
    const int *ran = native_swarm_ran(&n_ran);
    for (unsigned at = 0; at < n_ran; at++) {
        int i = ran[at];
        native_robot *r = native_swarm_robot(i);
        print_console(i, r);
        print_faults(i, r);
        if (opts->world != NULL)
            for (unsigned k = 0; k < r->log.n_motors; k++)
                world_run_motors(i, r->log.motors[k].left, r->log.motors[k].right,
                                 seconds_of(r, r->log.motors[k].at));
        if (r->log.n_sent != 0) senders[n_senders++] = i;
    }
    native_air_deliver(senders, n_senders);
    for (unsigned at = 0; at < n_ran; at++) native_log_clear(&native_swarm_robot(ran[at])->log);
}

/* ---- the run ---- */

/* With two threads or more in a world, one steps the physics while the
 * others run the robots (world_stepper.h): at a thousand packed robots a
 * step costs about what the robots do between two steps. */
static int physics_thread(const options *o) {
    return o->world != NULL && (o->threads >= 2 || (o->threads == 0 && sysconf(_SC_NPROCESSORS_ONLN) >= 2));
}

/* From this many robots the robots' side is the larger by far (10 000
 * packed robots: three quarters of the work, perf): they take every
 * thread asked for, and the physics' thread overlaps them, running while
 * the robots' threads wait for each other at the windows' ends. Below it
 * the physics weighs as much as the robots and keeps a thread's place. */
#define ROBOTS_BESIDE_PHYSICS 5000

/* The robots' threads: --threads, less the physics' own below
 * ROBOTS_BESIDE_PHYSICS robots. */
static int robot_threads(const options *o, int physics_on_own) {
    int asked = o->threads;
    if (physics_on_own && asked >= 2 && o->robots < ROBOTS_BESIDE_PHYSICS) asked--;
    return native_swarm_threads_for(asked, o->robots);
}

static int start(const options *o) {
    int on_own = physics_thread(o);
    int threads = robot_threads(o, on_own);
    native_apps apps;
    if (native_apps_load(o, threads, &apps) != 0) return -1;
    nominal_hz = apps.copies[0].entry.cpu_hz;
    native_counters_locate(&apps); /* --counters and ir.csv */
    if (native_swarm_create(apps.copies, apps.n, threads, apps.app_of, o->robots) != 0) return -1;
    lines = calloc((size_t)o->robots, sizeof *lines);
    senders = malloc((size_t)o->robots * sizeof *senders);
    if (lines == NULL || senders == NULL) return -1;
    uint64_t window = (uint64_t)llround(WINDOW_MS / 1000.0 * nominal_hz);
    native_air_start(o->robots, o->ir_range_mm, o->ir_loss_pct, o->ir_loss_seed, nominal_hz, window,
                     &o->ir_distance);
    if (native_faults_start(o) != 0) return -1;
    for (int i = 0; i < o->robots; i++) configure(i, o);
    if (o->world != NULL) {
        positions = malloc((size_t)o->robots * 2 * sizeof *positions);
        if (positions == NULL || world_run_start(o->robots, o, &native_robots, nominal_hz, on_own) != 0) return -1;
    } else {
        native_air_place(placement_distance_of, (void *)&o->place, NULL);
    }
    native_swarm_boot();
    native_faults_attach(nominal_hz);
    native_ohc_start(o, o->robots, nominal_hz);
    native_ohc_deliver(window);
    return 0;
}

static void run(const options *o) {
    uint64_t limit = (uint64_t)(o->seconds * (double)nominal_hz);
    uint64_t window = (uint64_t)llround(WINDOW_MS / 1000.0 * nominal_hz);
    uint64_t counters_every = o->counters_period > 0 ? (uint64_t)(o->counters_period * (double)nominal_hz) : 0;
    uint64_t next_counters = counters_every;
    progress_start(o->progress, o->robots, nominal_hz);
    for (uint64_t end = 0;;) {
        end += window;
        if (end > limit) end = limit;
        int all_stopped = native_swarm_window(end, nominal_hz, native_air_clear);
        after_window();
        native_faults_after_window(end);
        native_ohc_deliver(end + window);
        if (o->world != NULL) world_run_after_window(end, nominal_hz);
        progress_update(end);
        run_end = end;
        if (all_stopped || end == limit) break;
        if (interrupt_stop_here((double)end / nominal_hz)) break;
        if (counters_every != 0 && end >= next_counters) {
            native_counters_print(n_robots, (double)end / nominal_hz);
            next_counters += counters_every;
        }
    }
    if (o->counters_period >= 0) native_counters_print(n_robots, (double)run_end / nominal_hz);
    progress_end();
    native_swarm_end();
}

/* How the robots ended, as the exact mode reports it (main.c). */
static int report(const options *o) {
    int status = 0, running = 0, booted = 0, broken = 0;
    for (int i = 0; i < n_robots; i++) {
        native_robot *r = native_swarm_robot(i);
        double t = seconds_of(r, r->io->now);
        char prefix[32] = "";
        if (n_robots > 1) snprintf(prefix, sizeof prefix, "[robot %d] ", i);
        /* what its kernel lost or refused, as the exact mode warns of it */
        const uint16_t *counters = native_swarm_robot_stats(i);
        if (counters != NULL) kernel_loss_warnings(n_robots > 1 ? i : -1, ROBOT_KILOBOT, counters);
        native_handlers_report(i, n_robots > 1 ? i : -1, ROBOT_KILOBOT, firmware_of(o, i),
                               (double)run_end / nominal_hz);
        if (r->image_changed) {
            fprintf(stderr, "openswarm-sim: %sits RAM changed while it was not running: a stray "
                            "write from another robot's code; run the robots apart to find whose\n", prefix);
            broken = 1;
        }
        if (r->io->state == NATIVE_BOOTLOADER) {
            fprintf(stderr, "openswarm-sim: %sjumped to the bootloader (BOOT message) at %.6f s\n", prefix, t);
            booted = 1;
        } else if (r->io->state == NATIVE_STOPPED) {
            if (!o->quiet) fprintf(stderr, "openswarm-sim: %sstopped at %.6f s, status %d\n", prefix, t, r->io->status);
            if (status == 0) status = r->io->status;
        } else {
            running++;
            if (o->expect_stop)
                fprintf(stderr, "openswarm-sim: %sthe program did not stop within %.3f s of simulated "
                                "time; give it longer with --time\n", prefix, o->seconds);
        }
    }
    int warnings = warnings_print();
    if (native_air_overflowed() != 0)
        fprintf(stderr, "openswarm-sim: %llu frames found a robot's inbox full (%d frames): they "
                        "were lost\n", (unsigned long long)native_air_overflowed(), NATIVE_INBOX_ROOM);
    if (broken) return EXIT_CRASH;
    if (booted) return EXIT_BOOTLOADER;
    if (faults_reported != 0 && !o->allow_faults) {
        fprintf(stderr, "openswarm-sim: %u kernel fault%s (above): the run fails (--allow-faults if "
                        "the program provokes them on purpose)\n", faults_reported, faults_reported == 1 ? "" : "s");
        return EXIT_FAULT;
    }
    if (running && o->expect_stop) return EXIT_TIMEOUT;
    if (warnings_fail_run(warnings, o)) return EXIT_WARNINGS;
    if (running && !o->quiet) progress_summary(o->seconds, n_robots, 0);
    return status;
}

int native_run(const options *o) {
    opts = o;
    n_robots = o->robots;
    if (refuse_exact_only(o) != 0) return EXIT_USAGE;
    if (o->console_csv != NULL && (console_csv = console_csv_open(o->console_csv)) == NULL)
        return EXIT_USAGE;
    if (start(o) != 0) return EXIT_USAGE;
    run(o);
    for (int i = 0; i < n_robots; i++) {
        if (lines[i].len == 0) continue;
        lines[i].text[lines[i].len] = '\0'; /* a last line without its end */
        emit_line(i, lines[i].text, seconds_of(native_swarm_robot(i), native_swarm_robot(i)->io->now));
    }
    stdout_flush();
    int console_lost = console_csv != NULL && console_csv_close(console_csv, o->console_csv, NULL, 0);
    int written = o->world != NULL ? world_run_finish() : 0;
    if (faults_finish() != 0) written = -1;
    if (interrupt_caught())
        return interrupt_finish(o->world != NULL && o->out_dir != NULL ? output_written() : NULL);
    int status = report(o);
    return status == 0 && (written != 0 || console_lost) ? EXIT_USAGE : status;
}
