/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* Command line of openswarm-sim. */
#include <errno.h>
#include <getopt.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "sim.h"
#include "faults/faults.h"
#include "world/world_run.h"

#define DEFAULT_DISTANCE_MM 50
#define DEFAULT_IR_RANGE_MM 100 /* a Kilobot hears neighbours up to about 10 cm away */

/* The options that place the robots; at most one of them is given. */
typedef struct placement_options {
    int distance_mm;       /* -1: not given */
    const char *line;      /* --line SPACING */
    const char *positions; /* --positions FILE */
    int robots_given;
} placement_options;

/* A whole number in [lo, hi], or -1 after printing what was expected. */
static long number(const char *option, const char *text, long lo, long hi, const char *example) {
    char *end;
    errno = 0;
    long v = strtol(text, &end, 0);
    if (errno != 0 || *end != '\0' || v < lo || v > hi) {
        fprintf(stderr, "openswarm-sim: %s '%s': expected %ld..%ld, e.g. %s %s\n", option, text,
                lo, hi, option, example);
        return -1;
    }
    return v;
}

static int parse_calibration(const char *text, options *o) {
    int v[4];
    char extra;
    if (sscanf(text, "%d,%d,%d,%d%c", &v[0], &v[1], &v[2], &v[3], &extra) != 4) v[0] = -1;
    for (int i = 0; i < 4; i++) {
        if (v[i] < 0 || v[i] > 255) {
            fprintf(stderr, "openswarm-sim: --calibration '%s': expected four duties 0..255, "
                            "e.g. --calibration 70,70,65,68\n", text);
            return -1;
        }
    }
    memcpy(o->calibration, v, sizeof v);
    return 0;
}

/* A percentage from 0 to max, "20" or "20%"; -1 with a message naming the
 * option and an example. */
static int percentage(const char *option, const char *text, double max, const char *example,
                      double *out) {
    char *end;
    double v = strtod(text, &end);
    if (*end == '%') end++;
    if (*end != '\0' || !(v >= 0 && v <= max)) {
        fprintf(stderr, "openswarm-sim: %s '%s': expected a percentage from 0 to %g, e.g. %s %s\n",
                option, text, max, option, example);
        return -1;
    }
    *out = v;
    return 0;
}

/* --video-fps, --video-speed: a number in [lo, hi]; -1 with a message
 * naming the option and an example. */
static int video_rate(const char *option, const char *text, double lo, double hi, const char *example,
                      double *out) {
    char *end;
    double v = strtod(text, &end);
    if (end == text || *end != '\0' || !(v >= lo && v <= hi)) {
        fprintf(stderr, "openswarm-sim: %s '%s': expected a number from %g to %g, e.g. %s %s\n", option,
                text, lo, hi, option, example);
        return -1;
    }
    *out = v;
    return 0;
}

#define MAX_SECONDS 1000000 /* 11.6 days of robot time: 8e12 cycles, far from 64 bits' end */

static int parse_period(const char *text, options *o) {
    char *end;
    double v = strtod(text, &end);
    if (end == text || *end != '\0' || !(v >= 0 && v <= 1e6)) {
        fprintf(stderr, "openswarm-sim: --counters '%s': expected seconds between reports, 0..1000000 "
                        "(0: at the end only), e.g. --counters 600\n", text);
        return -1;
    }
    o->counters_period = v;
    return 0;
}

static int parse_time(const char *text, options *o) {
    char *end;
    o->seconds = strtod(text, &end);
    if (*end == 's') end++;
    /* !(a && b): NaN fails both (it never ended); inf and 3e12 ran in no time. */
    if (*end != '\0' || !(o->seconds > 0 && o->seconds <= MAX_SECONDS)) {
        fprintf(stderr, "openswarm-sim: --time '%s': expected seconds, more than 0 and at most %d, e.g. --time 2.5\n",
                text, MAX_SECONDS);
        return -1;
    }
    return 0;
}

static int place_robots(const placement_options *given, options *o) {
    int ways = (given->distance_mm >= 0) + (given->line != NULL) + (given->positions != NULL);
    if (ways > 1) {
        fprintf(stderr, "openswarm-sim: --distance, --line and --positions each place the robots: "
                        "give only one of them\n");
        return -1;
    }
    if (given->line != NULL) return placement_line(&o->place, o->robots, given->line);
    if (given->positions != NULL)
        return placement_file(&o->place, given->positions, &o->robots, given->robots_given);
    placement_all_at(&o->place, given->distance_mm >= 0 ? given->distance_mm : DEFAULT_DISTANCE_MM);
    return 0;
}

/* The FIRMWARE.elf arguments; several set the default robot count. */
static int take_firmware(int n, char **paths, placement_options *place, options *o) {
    if (n == 0 && o->world != NULL) return 0; /* the world may name every robot's */
    if (n == 0) {
        fprintf(stderr, "openswarm-sim: expected a FIRMWARE.elf (see --help)\n");
        return -1;
    }
    if (n > MAX_FIRMWARE) {
        fprintf(stderr, "openswarm-sim: %d firmware files: give at most %d (the last one runs on "
                        "the robots after it)\n", n, MAX_FIRMWARE);
        return -1;
    }
    for (int i = 0; i < n; i++) o->elves[i] = paths[i];
    o->n_elves = n;
    if (n > 1 && !place->robots_given && place->positions == NULL) o->robots = n;
    return 0;
}

/* The files given on the command line, before any is opened (the world
 * file's reader checks the firmware it names). */
static int inputs_are_regular(int n, char **paths, const placement_options *place, const options *o) {
    if (input_is_regular("--world", o->world, "give the world.json file itself (docs/world.md)") != 0 ||
        input_is_regular("--positions", place->positions,
                         "give a text file with one \"x y\" line (millimetres) per robot") != 0)
        return -1;
    for (int i = 0; i < n; i++)
        if (input_is_regular("the firmware", paths[i],
                             "give the FIRMWARE.elf (or .hex) file the build wrote, e.g. "
                             "build/kilobot/APP.elf") != 0)
            return -1;
    return 0;
}

/* --faults, repeatable: each adds to the spec. */
static int add_faults(const char *text, options *o) {
    if (o->faults == NULL && (o->faults = calloc(1, sizeof *o->faults)) == NULL) {
        fprintf(stderr, "openswarm-sim: out of memory for --faults\n");
        return -1;
    }
    return faults_parse(text, o->faults);
}

static int one_firmware(const options *o) {
    for (int i = 1; i < o->robots; i++)
        if (strcmp(firmware_of(o, i), firmware_of(o, 0)) != 0) return 0;
    return 1;
}

int parse_options(int argc, char **argv, options *o) {
    static const struct option longopts[] = {
        {"time", required_argument, 0, 't'},       {"robots", required_argument, 0, 'n'},
        {"expect-stop", no_argument, 0, 's'},      {"quiet", no_argument, 0, 'q'},
        {"marks", no_argument, 0, 'm'},            {"watch-irq", required_argument, 0, 'i'},
        {"profile", no_argument, 0, 'F'},
        {"trace", no_argument, 0, 'T'},            {"trace-csv", required_argument, 0, 'C'},
        {"console-csv", required_argument, 0, 'c' + 512},
        {"uid", required_argument, 0, 'U'},        {"calibration", required_argument, 0, 'K'},
        {"light", required_argument, 0, 'L'},      {"voltage", required_argument, 0, 'V'},
        {"temperature", required_argument, 0, 'E'}, {"gdb", required_argument, 0, 'G'},
        {"vcd", required_argument, 0, 'W'},        {"help", no_argument, 0, 'h'},
        {"distance", required_argument, 0, 'd'},   {"ohc", required_argument, 0, 'O'},
        {"line", required_argument, 0, 'N'},       {"positions", required_argument, 0, 'P'},
        {"ir-range", required_argument, 0, 'I'},   {"charging", no_argument, 0, 'H'},
        {"ir-log", no_argument, 0, 'R'},           {"clock-spread", required_argument, 0, 'S'},
        {"ir-loss", required_argument, 0, 'X'},
        {"world", required_argument, 0, 'w'},      {"out", required_argument, 0, 'o'},
        {"video", no_argument, 0, 'v'},            {"progress", no_argument, 0, 'p'},
        {"video-fps", required_argument, 0, 'F' + 512}, {"video-speed", required_argument, 0, 'S' + 512},
        {"ids", no_argument, 0, 'i' + 256},
        {"no-progress", no_argument, 0, 'P' + 256}, {"threads", required_argument, 0, 'j'},
        {"allow-faults", no_argument, 0, 'A' + 256}, {"strict", no_argument, 0, 's' + 256},
        {"mask-limit", required_argument, 0, 'M' + 256}, {"main-stack", no_argument, 0, 'S' + 256},
        {"timestamps", no_argument, 0, 'T' + 256},
        {"faults", required_argument, 0, 'f' + 256}, {"fault-log", required_argument, 0, 'l' + 256},
        {"counters", required_argument, 0, 'c' + 256},
        {"no-loop-skip", no_argument, 0, 'L' + 256},
        {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    o->seconds = 10.0;
    o->mask_limit_ms = 1000;
    o->robots = 1;
    o->ir_range_mm = DEFAULT_IR_RANGE_MM;
    placement_options place = {-1, NULL, NULL, 0};
    o->uid = -1;
    o->progress = -1;
    o->counters_period = -1;
    o->light_mv = o->voltage_mv = o->temperature_mv = -1;
    for (int i = 0; i < 4; i++) o->calibration[i] = -1;
    int c;
    long v = 0;
    while ((c = getopt_long(argc, argv, "t:n:d:sqmi:h", longopts, NULL)) != -1) {
        switch (c) {
        case 't': if (parse_time(optarg, o) != 0) return -1; o->given |= GIVEN_TIME; break;
        case 'n': if ((v = number("--robots", optarg, 1, MAX_ROBOTS, "2")) < 0) return -1; o->robots = (int)v; place.robots_given = 1; o->given |= GIVEN_ROBOTS; break;
        case 's': o->expect_stop = 1; break;
        case 'A' + 256: o->allow_faults = 1; break;
        case 's' + 256: o->strict = 1; break;
        case 'M' + 256: if ((v = number("--mask-limit", optarg, 0, 3600000, "1000")) < 0) return -1; o->mask_limit_ms = (double)v; break;
        case 'S' + 256: o->main_stack = 1; break;
        case 'T' + 256: o->timestamps = 1; break;
        case 'f' + 256: if (add_faults(optarg, o) != 0) return -1; break;
        case 'l' + 256: o->fault_log = optarg; break;
        case 'c' + 256: if (parse_period(optarg, o) != 0) return -1; break;
        case 'L' + 256: o->no_loop_skip = 1; break;
        case 'd': if ((v = number("--distance", optarg, 10, 1000, "40")) < 0) return -1; place.distance_mm = (int)v; o->given |= GIVEN_PLACEMENT; break;
        case 'N': place.line = optarg; o->given |= GIVEN_PLACEMENT; break;
        case 'P': place.positions = o->positions = optarg; o->given |= GIVEN_PLACEMENT; break;
        case 'I': if ((v = number("--ir-range", optarg, 10, 1000, "100")) < 0) return -1; o->ir_range_mm = (int)v; o->given |= GIVEN_IR_RANGE; break;
        case 'R': o->ir_log = 1; break;
        case 'S': if (percentage("--clock-spread", optarg, 5, "1", &o->clock_spread_pct) != 0) return -1; o->given |= GIVEN_CLOCK_SPREAD; break;
        case 'X': if (percentage("--ir-loss", optarg, 100, "20", &o->ir_loss_pct) != 0) return -1; o->given |= GIVEN_IR_LOSS; break;
        case 'q': o->quiet = 1; break;
        case 'm': o->marks = 1; break;
        case 'F': o->profile = 1; break;
        case 'i':
            if ((v = number("--watch-irq", optarg, 1, 255, "14")) < 0) return -1;
            if (o->n_watched == MAX_WATCHED_IRQS) {
                fprintf(stderr, "openswarm-sim: at most %d --watch-irq\n", MAX_WATCHED_IRQS);
                return -1;
            }
            o->watched[o->n_watched++] = (int)v;
            break;
        case 'T': o->trace = 1; break;
        case 'C': o->trace_csv = optarg; break;
        case 'U': if ((v = number("--uid", optarg, 0, 65535, "42")) < 0) return -1; o->uid = (int)v; o->given |= GIVEN_UID; break;
        case 'K': if (parse_calibration(optarg, o) != 0) return -1; o->given |= GIVEN_CALIBRATION; break;
        case 'L': if ((v = number("--light", optarg, 0, 5000, "1650")) < 0) return -1; o->light_mv = (int)v; o->given |= GIVEN_LIGHT; break;
        case 'V': if ((v = number("--voltage", optarg, 0, 5000, "3000")) < 0) return -1; o->voltage_mv = (int)v; break;
        case 'E': if ((v = number("--temperature", optarg, 0, 5000, "330")) < 0) return -1; o->temperature_mv = (int)v; break;
        case 'G': if ((v = number("--gdb", optarg, 1, 65535, "1234")) < 0) return -1; o->gdb_port = (int)v; break;
        case 'W': o->vcd = optarg; break;
        case 'H': o->charging = 1; break;
        case 'w': o->world = optarg; break;
        case 'c' + 512: o->console_csv = optarg; break;
        case 'o': o->out_dir = optarg; break;
        case 'v': o->video = 1; break;
        case 'F' + 512: if (video_rate("--video-fps", optarg, 1, 100, "10", &o->video_fps) != 0) return -1; break;
        case 'S' + 512: if (video_rate("--video-speed", optarg, 0.01, 10000, "10", &o->video_speed) != 0) return -1; break;
        case 'i' + 256: o->ids = 1; break;
        case 'p': o->progress = 1; break;
        case 'P' + 256: o->progress = 0; break;
        case 'j': if ((v = number("--threads", optarg, 1, 256, "2")) < 0) return -1; o->threads = (int)v; break;
        case 'O':
            if (o->n_ohc == MAX_OHC_MESSAGES) {
                fprintf(stderr, "openswarm-sim: at most %d --ohc messages\n", MAX_OHC_MESSAGES);
                return -1;
            }
            if (ohc_parse(optarg, &o->ohc[o->n_ohc++]) != 0) return -1;
            break;
        case 'h': options_usage(stdout); exit(0);
        default: options_usage(stderr); return -1;
        }
    }
    if (inputs_are_regular(argc - optind, argv + optind, &place, o) != 0) return -1;
    if (take_firmware(argc - optind, argv + optind, &place, o) != 0) return -1;
    if ((o->video_fps > 0 || o->video_speed > 0) && !o->video) {
        fprintf(stderr, "openswarm-sim: --video-fps and --video-speed set the rate of --video's "
                        "video.mp4: give --video too, or drop them\n");
        return -1;
    }
    if (o->world != NULL) return world_options_check(o);
    if (o->out_dir != NULL || o->video || o->ids) {
        fprintf(stderr, "openswarm-sim: --out, --video and --ids record robots moving in a world: give "
                        "--world FILE too (docs/world.md)\n");
        return -1;
    }
    if (place_robots(&place, o) != 0) return -1;
    return options_check_robots(o);
}

/* The checks that need the robots' count: after a placement option or a
 * world file set it. */
int options_check_robots(options *o) {
    if (outputs_apart_from_inputs(o) != 0) return -1;
    if (o->fault_log != NULL && o->faults == NULL) {
        fprintf(stderr, "openswarm-sim: --fault-log %s logs injected faults: give --faults SPEC too\n",
                o->fault_log);
        return -1;
    }
    if (o->faults != NULL) {
        o->faults->log_path = o->fault_log;
        if (faults_check(o->faults, o->robots, o->seconds) != 0) return -1;
    }
    if (o->n_elves > o->robots) {
        fprintf(stderr, "openswarm-sim: %d firmware files for %d robots: give at most one per robot "
                        "(the last one also runs on the robots after it)\n", o->n_elves, o->robots);
        return -1;
    }
    if (o->profile && o->robots == 0) {
        fprintf(stderr, "openswarm-sim: --profile counts the cycles of the robots' firmware, and %s has "
                        "no robots: drop --profile, or add robots to it\n", o->world ? o->world : "the run");
        return -1;
    }
    if (o->profile && !one_firmware(o)) {
        fprintf(stderr, "openswarm-sim: --profile names the functions of one firmware: run one "
                        "FIRMWARE.elf on every robot\n");
        return -1;
    }
    if (o->robots > 1 && (o->gdb_port != 0 || o->vcd != NULL)) {
        fprintf(stderr, "openswarm-sim: --gdb and --vcd follow one robot: drop --robots (or "
                        "use a world of one robot)\n");
        return -1;
    }
    for (int i = 0; i < o->n_ohc; i++) {
        if (o->ohc[i].seconds > o->seconds) {
            fprintf(stderr, "openswarm-sim: --ohc at %g s: after the end of the run (--time %g); give a time "
                            "within it, or a longer --time\n", o->ohc[i].seconds, o->seconds);
            return -1;
        }
    }
    if (o->robots > 1 && o->uid < 0) o->uid = 1;
    if (o->uid >= 0 && o->uid + o->robots - 1 > 65535) {
        fprintf(stderr, "openswarm-sim: --uid %d: robot ids would pass 65535\n", o->uid);
        return -1;
    }
    return 0;
}

const char *firmware_of(const options *o, int index) {
    if (o->robot_elf != NULL) return o->robot_elf[index];
    if (o->n_elves <= 0) return NULL;
    int k = index < o->n_elves ? index : o->n_elves - 1;
    return o->elves[k < 0 ? 0 : k];
}
