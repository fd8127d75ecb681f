/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The options a run in a world refuses before it starts (world_refusals.h). */
#include "world/world_refusals.h"

#include <math.h>
#include <stdio.h>

#include "output/output.h"

/* Options a world sets itself: refused beside it, with where to set them. */
int world_refuse_owned_options(const options *o) {
    static const struct {
        unsigned bit;
        const char *option, *instead;
    } owned[] = {
        {GIVEN_ROBOTS, "--robots", "robots[] (count, poses, grid)"},
        {GIVEN_PLACEMENT, "--distance, --line and --positions", "robots[] (poses, region, grid)"},
        {GIVEN_UID, "--uid", "robots[].uid"},
        {GIVEN_CALIBRATION, "--calibration", "robots[].calibration"},
        {GIVEN_LIGHT, "--light", "light.ambient_mv and light.sources"},
    };
    for (size_t i = 0; i < sizeof owned / sizeof owned[0]; i++) {
        if (!(o->given & owned[i].bit)) continue;
        fprintf(stderr, "openswarm-sim: %s: the world file %s sets this; drop the option and set "
                        "%s there (docs/world.md)\n", owned[i].option, o->world, owned[i].instead);
        return -1;
    }
    return 0;
}

/* e-pucks are host processes, not simulated MCUs (epuck_run.c): the
 * options that watch or drive a Kilobot's MCU, IR or overhead controller
 * are refused by name, not ignored. Checked before the world's own values
 * fill the options in. */
int world_refuse_kilobot_only(const options *o) {
    const char *what = o->n_ohc ? "--ohc" : o->counters_period >= 0 ? "--counters"
                     : o->ir_log ? "--ir-log" : (o->given & GIVEN_CLOCK_SPREAD) ? "--clock-spread"
                     : (o->given & GIVEN_IR_RANGE) ? "--ir-range" : (o->given & GIVEN_IR_LOSS) ? "--ir-loss"
                     : o->faults ? "--faults" : o->fault_log ? "--fault-log"
                     : o->trace ? "--trace" : o->trace_csv ? "--trace-csv" : o->vcd ? "--vcd"
                     : o->gdb_port ? "--gdb" : o->marks ? "--marks" : o->n_watched ? "--watch-irq"
                     : o->profile ? "--profile" : o->main_stack ? "--main-stack"
                     : o->timestamps ? "--timestamps" : o->charging ? "--charging"
                     : o->voltage_mv >= 0 ? "--voltage" : o->temperature_mv >= 0 ? "--temperature"
                     : o->expect_stop ? "--expect-stop" : NULL;
    if (what == NULL) return 0;
    fprintf(stderr, "openswarm-sim: %s: Kilobots only (their simulated MCU, IR or overhead controller), "
                    "and %s holds e-pucks: drop %s (docs/world.md, \"e-pucks in the world\")\n",
            what, o->world, what);
    return -1;
}

/* Every sample writes a row a robot and a row an object: at most
 * OUTPUT_MAX_ROWS of them, checked before the run. */
int world_sample_count_check(const options *o, const world_spec *spec) {
    double things = (double)spec->n_robots + spec->n_objects;
    double samples = floor(o->seconds / spec->sample_period_s + 1e-9) + 1, rows = things * samples;
    if (o->out_dir == NULL || rows <= OUTPUT_MAX_ROWS) return 0;
    double bytes = samples * (spec->n_robots * 40.0 + spec->n_objects * 25.0); /* a row's text */
    /* the shortest period that fits, rounded up to 3 significant digits */
    double least = o->seconds / (floor(OUTPUT_MAX_ROWS / things) - 1), unit = pow(10, floor(log10(least)) - 2);
    least = ceil(least / unit - 1e-9) * unit;
    const char *kind = spec->robot_kind == WORLD_ROBOT_EPUCK ? "e-puck" : "robot";
    char who[64] = "", objects[64] = "";
    if (spec->n_robots > 0) snprintf(who, sizeof who, "%d %s%s", spec->n_robots, kind, spec->n_robots == 1 ? "" : "s");
    if (spec->n_objects > 0)
        snprintf(objects, sizeof objects, "%s%d object%s", who[0] ? " and " : "", spec->n_objects,
                 spec->n_objects == 1 ? "" : "s");
    fprintf(stderr, "openswarm-sim: --out %s: %s%s sampled every %g s for %g s make %.3g rows of "
                    "trajectories.csv and objects.csv (about %.0f %s); at most %.0f are written: a "
                    "sample_period_s of at least %g s in %s, a shorter run (--time or duration_s), or no --out\n",
            o->out_dir, who, objects, spec->sample_period_s, o->seconds, rows,
            bytes >= 1e9 ? bytes / 1e9 : bytes / 1e6, bytes >= 1e9 ? "GB" : "MB", OUTPUT_MAX_ROWS, least,
            spec->path);
    return -1;
}
