/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* openswarm-sim: load the robots, run them in lockstep, report how they ended. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <sim_cycle_timers.h>

#include "sim.h"
#include "board/invalid_opcode.h"
#include "faults/faults.h"
#include "interrupt.h"
#include "lockstep.h"
#include "output/output.h"
#include "native/native_apps.h"
#include "native/native_load.h"
#include "native/native_run.h"
#include "progress.h"
#include "world/world_avr.h"
#include "world/world_run.h"

/* Robots advance together in windows this many cycles long; what one
 * sends in a window reaches the others, exactly one window later, in the
 * next (air/ir_channel.c). */
#define LOCKSTEP_CYCLES IR_LATENCY_CYCLES

static robot *robots;

/* The ELF's clock: the lockstep windows count its cycles. */
static uint32_t nominal_hz;

/* Robot index's clock error as a fraction of --clock-spread: evenly from -1
 * to +1 over the n robots, in an order scrambled by a fixed hash so that
 * robots next to each other by index do not run alike. */
double robot_clock_error(int index, int n) {
    if (n < 2) return 0.0;
    uint32_t mine = (uint32_t)index * 2654435761u;
    int rank = 0;
    for (int j = 0; j < n; j++) {
        uint32_t other = (uint32_t)j * 2654435761u;
        if (other < mine || (other == mine && j < index)) rank++;
    }
    return 2.0 * rank / (n - 1) - 1.0;
}

static int setup_robot(robot *r, int index, const options *o, FILE *csv) {
    r->index = index;
    r->state = cpu_Running;
    const char *elf = firmware_of(o, index);
    r->avr = firmware_load(elf);
    if (r->avr == NULL) return -1;
    main_stack_paint(r, elf);
    stack_watch_attach(r, elf);
    register_store_watch_attach(r, elf);
    invalid_opcode_attach(r);
    firmware_counters_locate(r, elf); /* the warnings at the end read them */
    handler_watch_attach(r, elf);
    if (index == 0) {
        nominal_hz = r->avr->frequency;
    } else if (r->avr->frequency != nominal_hz) {
        fprintf(stderr, "openswarm-sim: %s runs at %u Hz, %s at %u Hz: robots in lockstep share "
                        "one clock rate (--clock-spread varies it)\n",
                elf, (unsigned)r->avr->frequency, o->elves[0], (unsigned)nominal_hz);
        return -1;
    }
    if (o->clock_spread_pct != 0)
        r->avr->frequency = (uint32_t)lround(
            nominal_hz * (1.0 + o->clock_spread_pct / 100.0 * robot_clock_error(index, o->robots)));
    r->avr->frequency = faults_clock_rate(index, r->avr->frequency);
    int uid = o->uid >= 0 ? o->uid + index : -1, calibration[4];
    memcpy(calibration, o->calibration, sizeof calibration);
    if (o->world != NULL) {
        world_robot_identity(index, &uid, calibration);
        world_avr_robot_noise(r, index);
    }
    board_configure(r->avr, o, uid, calibration);
    if (o->world != NULL) world_eeprom_fill(board_eeprom_write, r->avr);
    if (faults_blank_calibration(index)) kilobot_eeprom_erase_calibration(board_eeprom_write, r->avr);
    adc_trigger_attach(r->avr);
    char prefix[sizeof r->console.prefix] = "";
    if (o->robots > 1) snprintf(prefix, sizeof prefix, "[robot %d] ", index);
    console_attach(r, o->quiet, o->timestamps, prefix, o->console_csv != NULL);
    if (o->trace || csv != NULL || o->world != NULL) trace_attach(r, o->trace, csv);
    if (measure_attach(r, o) != 0) return -1;
    return debug_attach(r, o);
}

/* A crash: where, and what to look for. A PC past the flash is ours to
 * catch (lockstep.c), so it is still there to name. */
static void report_crash(const robot *r, const options *o, double t) {
    if (invalid_opcode_report(r, firmware_of(o, r->index), t)) return;
    if (!pc_in_flash(r->avr)) {
        fprintf(stderr, "openswarm-sim: robot %d (%s) crashed at %.6f s: its program counter left the "
                        "flash: PC 0x%x, past its end at 0x%x. A return through a stack overwritten or "
                        "freed too far (a thread's stack too small in openswarm.json, assembly that "
                        "moves SP) or a call through a bad function pointer; run it with avr-gdb "
                        "(openswarm run --gdb 1234) and step to the return that jumps there\n",
                r->index, firmware_of(o, r->index), t, (unsigned)r->avr->pc, (unsigned)r->avr->flashend);
        return;
    }
    char place[400];
    fprintf(stderr, "openswarm-sim: %sthe firmware crashed at %.6f s in %s: a bad "
                    "jump or a stack overflow; run it with avr-gdb to see where\n",
            r->console.prefix, t, code_place(firmware_of(o, r->index), r->avr->pc, place, sizeof place));
}

/* The robots' cycles fast-forwarded over loops (loop_skip.h), for the summary. */
static uint64_t skipped_cycles;

/* Of all the robots' cycles. */
static double skipped_share(int n) {
    double all = 0;
    for (int i = 0; i < n; i++) all += (double)robots[i].avr->cycle;
    return all > 0 ? (double)skipped_cycles / all : 0.0;
}

static int report(int n, const options *o) {
    int status = 0, crashed = 0, running = 0, booted = 0, hung = 0, memory_broken = 0;
    unsigned faults = 0;
    for (int i = 0; i < n; i++) {
        robot *r = &robots[i];
        faults += r->console.faults;
        firmware_warnings_report(r);
        hung |= r->hung;
        /* a stack past its room, a store into the registers: told when it happened */
        memory_broken |= main_stack_report(r, o->main_stack);
        memory_broken |= r->stack_watch.overflowed != STACKS_KEPT || r->stored_to_register;
        double t = (double)r->avr->cycle / (double)r->avr->frequency;
        if (robot_at_bootloader(r)) {
            fprintf(stderr, "openswarm-sim: robot %d jumped to the bootloader (BOOT message) at "
                            "%.6f s: on a robot the overhead controller would now reprogram it\n",
                    r->index, t);
            booted = 1;
        } else if (r->state == cpu_Crashed) {
            report_crash(r, o, t);
            crashed = 1;
        } else if (r->state == cpu_Done) {
            int s = r->avr->data[GPIOR0_ADDR];
            if (!o->quiet) fprintf(stderr, "openswarm-sim: %sstopped at %.6f s, status %d\n",
                                   r->console.prefix, t, s);
            if (status == 0) status = s;
        } else {
            running++;
            if (o->expect_stop)
                fprintf(stderr, "openswarm-sim: %sthe firmware did not stop within %.3f s of "
                                "simulated time (PC 0x%04x); give it longer with --time\n",
                        r->console.prefix, o->seconds, (unsigned)r->avr->pc);
        }
    }
    int warnings = warnings_print();
    if (crashed) return EXIT_CRASH;
    if (booted) return EXIT_BOOTLOADER;
    if (hung) return EXIT_HANG;
    if (memory_broken && !o->allow_faults) return EXIT_FAULT;
    if (faults != 0 && !o->allow_faults) {
        fprintf(stderr, "openswarm-sim: %u kernel fault%s (above): the run fails (--allow-faults if "
                        "the firmware provokes them on purpose)\n",
                faults, faults == 1 ? "" : "s");
        return EXIT_FAULT;
    }
    if (running && o->expect_stop) return EXIT_TIMEOUT;
    if (warnings_fail_run(warnings, o)) return EXIT_WARNINGS;
    if (running && !o->quiet) progress_summary(o->seconds, n, skipped_share(n));
    return status;
}

/* Which robots run which firmware, when they differ: "robot 0 runs
 * a.elf; robots 1..3 run b.elf". */
static void print_firmware_legend(const options *o) {
    fprintf(stderr, "openswarm-sim: ");
    for (int i = 0; i < o->n_elves; i++) {
        int last = i == o->n_elves - 1 ? o->robots - 1 : i;
        if (last == i)
            fprintf(stderr, "%srobot %d runs %s", i ? "; " : "", i, o->elves[i]);
        else
            fprintf(stderr, "%srobots %d..%d run %s", i ? "; " : "", i, last, o->elves[i]);
    }
    fprintf(stderr, "\n");
}

static int load_robots(const options *o, FILE *csv) {
    /* A world may hold no robots (docs/world.md): its time still runs, by
     * the clock robots would have. */
    nominal_hz = KILOBOT_CLOCK_HZ;
    robots = calloc(o->robots > 0 ? (size_t)o->robots : 1, sizeof *robots);
    if (robots == NULL) {
        fprintf(stderr, "openswarm-sim: out of memory for %d robots\n", o->robots);
        return -1;
    }
    for (int i = 0; i < o->robots; i++)
        if (setup_robot(&robots[i], i, o, csv) != 0) return -1;
    ir_channel_attach(robots, o->robots, o->ir_range_mm, o->ir_loss_pct, o->ir_loss_seed, &o->ir_distance);
    if (o->world == NULL) ir_channel_place(placement_distance_of, (void *)&o->place);
    else if (world_avr_start(robots, o->robots, o, nominal_hz) != 0) return -1;
    return 0;
}

/* --counters: every robot's, at the nominal clock's cycle now. */
static void print_counters(const options *o, avr_cycle_count_t now) {
    for (int i = 0; i < o->robots; i++)
        firmware_counters_print(&robots[i], (double)now / nominal_hz);
    stdout_flush();
}

/* --console-csv: the lines robots finished in each window, written after
 * it. */
static FILE *console_csv;

/* The robots in lockstep windows until the time is up or all stopped; -1
 * after a message if they could not start. */
static int run(const options *o) {
    avr_cycle_count_t limit = (avr_cycle_count_t)(o->seconds * (double)nominal_hz);
    /* -1 (no --counters) is not a period: converted to cycles, a negative
     * number is undefined behaviour (UBSan, fuzz_sim_faults) */
    avr_cycle_count_t counters_every =
        o->counters_period > 0 ? (avr_cycle_count_t)(o->counters_period * (double)nominal_hz) : 0;
    avr_cycle_count_t next_counters = counters_every;
    /* Skipping would hide instructions from the debugger and the profile. */
    int skip = !o->no_loop_skip && o->gdb_port == 0 && !o->profile;
    if (lockstep_begin(robots, o->robots, nominal_hz, o->threads, o->profile, skip) != 0) return -1;
    progress_start(o->progress, o->robots, nominal_hz);
    for (avr_cycle_count_t end = 0;;) {
        end += LOCKSTEP_CYCLES;
        if (end > limit) end = limit;
        int all_stopped = lockstep_window(end);
        if (console_csv != NULL) console_csv_write(console_csv, robots, o->robots);
        ir_channel_hand_over(LOCKSTEP_CYCLES);
        faults_after_window(end);
        if (o->world != NULL) world_run_after_window(end, nominal_hz);
        for (int i = 0; i < o->robots; i++) {
            interrupt_watch_check(&robots[i], o->mask_limit_ms);
            fault_place_after_window(&robots[i], firmware_of(o, i));
        }
        progress_update(end);
        if ((all_stopped && o->robots > 0) || end == limit) break; /* none: run to the end */
        if (interrupt_stop_here((double)end / nominal_hz)) break;
        if (counters_every != 0 && end >= next_counters) {
            lockstep_settle_all();
            print_counters(o, end);
            next_counters += counters_every;
        }
    }
    lockstep_settle_all(); /* the robots as they stopped, not at a loop's head */
    if (o->counters_period >= 0 && o->robots > 0)
        print_counters(o, robots[0].avr->cycle * (uint64_t)nominal_hz / robots[0].avr->frequency);
    progress_end();
    skipped_cycles = lockstep_skipped_cycles();
    lockstep_end();
    return 0;
}

static int run_main(int argc, char **argv) {
    options o;
    if (parse_options(argc, argv, &o) != 0) return EXIT_USAGE;
    if (o.world != NULL && world_run_is_epuck()) { /* the Kilobot-only options refused (world_run.c) */
        if (o.console_csv != NULL) {
            fprintf(stderr, "openswarm-sim: --console-csv keeps Kilobots' consoles; %s holds e-pucks, "
                            "whose controllers print on the simulator's standard output: drop "
                            "--console-csv\n", o.world);
            return EXIT_USAGE;
        }
        return world_run_epucks(&o);
    }
    if (firmware_of(&o, 0) != NULL && native_apps_one_mode(&o) != 0) return EXIT_USAGE;
    if (firmware_of(&o, 0) != NULL && native_is_robot(firmware_of(&o, 0))) return native_run(&o);
    if (o.world != NULL && world_run_is_native()) {
        fprintf(stderr, "openswarm-sim: %s asks for \"fidelity\": \"native\", and %s is firmware for "
                        "the exact mode: give the app built for the host (`openswarm build --native`: "
                        "build/kilobot-native/<app>.so), or drop \"fidelity\" from the world\n",
                o.world, firmware_of(&o, 0));
        return EXIT_USAGE;
    }
    for (int i = 0; i < o.robots; i++)
        if ((i == 0 || firmware_of(&o, i) != firmware_of(&o, i - 1)) &&
            firmware_check(firmware_of(&o, i)) != 0)
            return EXIT_USAGE;
    if (o.profile && profile_load(firmware_of(&o, 0)) != 0) return EXIT_USAGE;
    FILE *csv = NULL;
    if (o.trace_csv != NULL) {
        csv = fopen(o.trace_csv, "w");
        if (csv == NULL) {
            fprintf(stderr, "openswarm-sim: --trace-csv %s: %s\n", o.trace_csv, strerror(errno));
            return EXIT_USAGE;
        }
        fprintf(csv, "time_s,cycle,robot,device,a,b,c\n");
    }
    if (o.console_csv != NULL && (console_csv = console_csv_open(o.console_csv)) == NULL)
        return EXIT_USAGE;
    if (o.faults != NULL && faults_start(o.faults, o.robots) != 0) return EXIT_USAGE;
    if (load_robots(&o, csv) != 0) return EXIT_USAGE;
    if (o.robots > 1 && !o.quiet && o.uid >= 0) /* "[robot 0]" is an index; programs see the uid */
        fprintf(stderr, "openswarm-sim: robots 0..%d have uids %d..%d\n", o.robots - 1, o.uid,
                o.uid + o.robots - 1);
    if (o.n_elves > 1 && !o.quiet && o.world == NULL) print_firmware_legend(&o);
    if (o.ir_log) ir_log_enable(o.robots);
    ohc_attach(robots, o.robots, &o);
    faults_attach(power_cycle_robots(robots, nominal_hz), nominal_hz);

    if (run(&o) != 0) return EXIT_USAGE;
    int written = 0; /* -1: an output could not be written (reported) */
    for (int i = 0; i < o.robots; i++) {
        if (csv != NULL || o.trace) trace_flush(&robots[i]);
        if (debug_detach(&robots[i]) != 0) written = -1;
    }
    if (csv != NULL) {
        char what[4200];
        snprintf(what, sizeof what, "--trace-csv %s", o.trace_csv);
        if (written_close(csv, what, 1) != 0) written = -1;
    }
    int console_lost = console_csv != NULL && console_csv_close(console_csv, o.console_csv, robots, o.robots);
    if (o.profile) profile_print(o.robots);
    if (faults_finish() != 0) written = -1;
    if (o.world != NULL && world_run_finish() != 0) written = -1;
    if (interrupt_caught()) return interrupt_finish(o.world != NULL && o.out_dir != NULL ? output_written() : NULL);
    int status = report(o.robots, &o);
    return status == 0 && (written != 0 || console_lost) ? EXIT_USAGE : status;
}

/* Whatever the run printed reached the standard output, or the run fails
 * (a full disk under `> log` left the consoles cut short, exit 0). */
int main(int argc, char **argv) {
    interrupt_catch();
    int status = run_main(argc, argv);
    if (written_close(stdout, "the standard output", 0) != 0 && status == 0) status = EXIT_USAGE;
    return status;
}
