/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* A run in a world (world_run.h). The physics steps every WORLD_STEP_S of
 * simulated time, begun when the robots' lockstep windows reach it; the
 * firmware's motor changes reach it at their exact time, so a 15 ms
 * spin-up pulse counts as 15 ms. The step runs while the robots go on
 * (world_stepper.h); WORLD_STEPS_AHEAD steps later the IR channel learns
 * the distances and the light sensors the light it left: what the robots
 * sense is two steps (20 ms, 0.2 mm of a Kilobot's walk) older than their
 * clock, and a sample shows the world as it was at its own time. */
#include "world/world_run.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "interrupt.h"
#include "output/output.h"
#include "world/epuck_link.h"
#include "world/epuck_run.h"
#include "native/native_epuck.h"
#include "native/native_load.h"
#include "world/kilobot_light.h"
#include "world/world.h"
#include "world/world_refusals.h"
#include "world/world_stepper.h"

#define ROOM_TEMPERATURE_MV 314   /* the ATmega328P's sensor at 25 C (datasheet) */

static world_spec spec;
static world *physics;
static const world_robots *robots; /* how to reach them */
static int n_robots;
static avr_cycle_count_t step_cycles, next_step;
/* What a step's sample shows besides the poses, noted as the step begins
 * (at its time) and taken with its poses WORLD_STEPS_AHEAD steps later:
 * step k's in notes[k % WORLD_STEPS_AHEAD]. */
typedef struct step_notes {
    double t;
    int sample_due;     /* a sample at t: the LEDs and IR counts noted */
    int frame_due;      /* the video's, at its own times: the LEDs noted */
    uint8_t *leds;      /* 3 a robot: red, green, blue */
    output_ir *ir;      /* each robot's counts at t */
} step_notes;
static step_notes notes[WORLD_STEPS_AHEAD];
static unsigned steps_noted, steps_seen;
static double end_s;     /* the run's end: the video's frames come before it */
static double next_sample_s, next_frame_s;
static int recording;
static int sample_failed; /* a sample could not be written (reported) */
static output_robot *poses;
static world_point *object_centres;
static output_link *links;
static int links_room;
static int *light_mv; /* last applied to each robot's ADC7, -1 none */
static double ir_range_mm;

static void *allocate(size_t n, size_t size) {
    void *p = calloc(n ? n : 1, size);
    if (p == NULL) {
        fprintf(stderr, "openswarm-sim: out of memory for the world's %zu items\n", n);
        exit(EXIT_CRASH);
    }
    return p;
}

/* Robots whose group names no firmware run the command line's ELFs: the
 * k-th such robot the k-th ELF, the last ELF the rest. */
static int assign_firmware(options *o) {
    const char **elf = allocate((size_t)spec.n_robots, sizeof *elf);
    int unnamed = 0;
    for (int i = 0; i < spec.n_robots; i++) {
        int f = spec.robots[i].firmware;
        if (f >= 0) {
            elf[i] = spec.firmware[f];
            continue;
        }
        if (o->n_elves == 0) {
            fprintf(stderr, "%s: robot %d (uid %d) has no firmware: give FIRMWARE.elf on the command "
                            "line, or \"firmware\" in its group of robots[]\n",
                    spec.path, i, spec.robots[i].uid);
            free(elf);
            return -1;
        }
        elf[i] = o->elves[unnamed < o->n_elves ? unnamed : o->n_elves - 1];
        unnamed++;
    }
    if (o->n_elves > unnamed) {
        fprintf(stderr, "openswarm-sim: %d firmware files for the %d robots of %s that name none: "
                        "give at most one per such robot\n", o->n_elves, unnamed, spec.path);
        free(elf);
        return -1;
    }
    o->robot_elf = elf;
    return 0;
}

int world_options_check(options *o) {
    if (world_refuse_owned_options(o) != 0 || world_spec_load(o->world, &spec) != 0) return -1;
    if (spec.robot_kind == WORLD_ROBOT_EPUCK && world_refuse_kilobot_only(o) != 0) return -1;
    o->robots = spec.n_robots;
    if (!(o->given & GIVEN_TIME) && spec.duration_s > 0) o->seconds = spec.duration_s;
    if (!(o->given & GIVEN_IR_RANGE) && spec.ir_range_mm > 0) o->ir_range_mm = spec.ir_range_mm;
    if (!(o->given & GIVEN_IR_LOSS) && spec.ir_loss_pct >= 0) o->ir_loss_pct = spec.ir_loss_pct;
    /* Its own draws: not the robots' streams (world.cpp), which take the
     * seed as it is. */
    o->ir_distance = (ir_distance_error){spec.ir_distance_bias_mm, spec.ir_distance_noise_mm,
                                         (uint64_t)spec.seed ^ 0x49524469737400ull};
    o->ir_loss_seed = (uint64_t)spec.seed ^ 0x49524C6F7373ull; /* "IRLoss" */
    if (!(o->given & GIVEN_CLOCK_SPREAD) && spec.clock_spread_pct >= 0)
        o->clock_spread_pct = spec.clock_spread_pct;
    if (o->temperature_mv < 0) o->temperature_mv = ROOM_TEMPERATURE_MV;
    if (assign_firmware(o) != 0) return -1;
    if (o->video && o->out_dir == NULL) {
        fprintf(stderr, "openswarm-sim: --video records the run into --out DIR's video.mp4: give "
                        "--out DIR too, or drop --video\n");
        return -1;
    }
    if (o->ids && o->out_dir == NULL) {
        fprintf(stderr, "openswarm-sim: --ids numbers the robots in --out DIR's final.png: give "
                        "--out DIR too, or drop --ids\n");
        return -1;
    }
    output_options out = {.dir = o->out_dir, .video = o->video, .quiet = o->quiet,
                          .ids = o->ids, .video_fps = o->video_fps, .video_speed = o->video_speed};
    if (o->out_dir != NULL && output_check(&out) != 0) return -1;
    if (world_sample_count_check(o, &spec) != 0) return -1;
    int status = options_check_robots(o);
    o->uid = -1; /* each robot's comes from the world */
    if (status != 0) return -1;
    physics = world_create(&spec);
    return 0;
}

uint64_t world_robot_noise_seed(int index) {
    uint64_t seed = (uint64_t)spec.seed * 0x9E3779B97F4A7C15ull ^ ((uint64_t)index << 32 | 0xA5A5u);
    world_random_next(&seed);
    return seed;
}

void world_robot_identity(int index, int *uid, int calibration[4]) {
    const world_robot *r = &spec.robots[index];
    *uid = r->uid;
    int own[4];
    kilobot_motors_calibration(world_robot_motors(physics, index), own);
    for (int i = 0; i < 4; i++) calibration[i] = r->calibration[i] == -2 ? own[i] : r->calibration[i];
}

const char *world_robot_group(int index, int *group) {
    if (spec.path == NULL || index >= spec.n_robots) return NULL;
    *group = spec.robots[index].group;
    return spec.path;
}

void world_eeprom_fill(eeprom_write_fn write, void *ctx) {
    for (uint16_t a = 0; a < WORLD_EEPROM_BYTES; a++)
        if (spec.eeprom_given[a]) write(ctx, a, &spec.eeprom[a], 1);
}

void world_run_motors(int index, uint8_t left, uint8_t right, double t) {
    world_stepper_motor(index, 0, left, t);
    world_stepper_motor(index, 1, right, t);
}

/* As the IR channel sees it: an obstacle between two robots in range puts
 * them out of it. The arena's walls never stand between two robots in it,
 * so without obstacles no ray is cast. */
static double distance_between(int a, int b, void *ctx) {
    (void)ctx;
    const output_robot *p = &poses[a], *q = &poses[b];
    double d = hypot(p->x_mm - q->x_mm, p->y_mm - q->y_mm);
    if (d <= ir_range_mm && spec.n_obstacles > 0 &&
        world_blocks_ir(physics, p->x_mm, p->y_mm, q->x_mm, q->y_mm))
        return INFINITY;
    return d;
}

static void sense_light(int i) {
    const output_robot *p = &poses[i];
    int mv = (int)lround(kilobot_light_mv(&spec, p->x_mm, p->y_mm, p->heading_deg));
    if (mv > KILOBOT_AVCC_MV) mv = KILOBOT_AVCC_MV; /* the input clips at the supply */
    if (mv == light_mv[i]) return;
    light_mv[i] = mv;
    robots->light(i, mv);
}

/* Where the robots are seen now (poses), for the channel and the sensors. */
static void sense(void) {
    if (spec.n_lights > 0 || spec.ambient_light_mv > 0)
        for (int i = 0; i < n_robots; i++) sense_light(i);
    robots->place(distance_between, NULL);
}

/* Where everything is before the first step. */
static void observe_start(void) {
    for (int i = 0; i < n_robots; i++) world_robot_pose(physics, i, &poses[i].x_mm, &poses[i].y_mm, &poses[i].heading_deg);
    for (int k = 0; k < spec.n_objects; k++)
        world_object_position(physics, k, &object_centres[k].x, &object_centres[k].y);
    sense();
}

static int *reached_by; /* scratch: the receivers one sender reaches */

/* Every pair in IR range now, sender first. */
static int collect_links(void) {
    int n_links = 0;
    for (int i = 0; i < n_robots; i++) {
        int reached = robots->links(i, reached_by, n_robots);
        if (n_links + reached > links_room) {
            links_room = (n_links + reached) * 2;
            links = realloc(links, (size_t)links_room * sizeof *links);
            if (links == NULL) exit(EXIT_CRASH);
        }
        for (int k = 0; k < reached; k++) links[n_links++] = (output_link){i, reached_by[k]};
    }
    return n_links;
}

/* The LEDs as they show now, for the sample of now. */
static void note_leds(uint8_t *leds) {
    for (int i = 0; i < n_robots; i++) robots->led(i, &leds[3 * i]);
}

static void show_leds(const uint8_t *leds) {
    for (int i = 0; i < n_robots; i++) {
        poses[i].led_r = leds[3 * i];
        poses[i].led_g = leds[3 * i + 1];
        poses[i].led_b = leds[3 * i + 2];
    }
}

/* Where everything was at t (poses, objects and LEDs as they were then). */
static int sample(double t, const output_ir *ir) {
    int n_links = collect_links();
    output_sample s = {t, poses, object_centres, links, n_links, ir};
    return output_sample_add(&s);
}

/* The same for the video, at its own times (it draws no links). */
static int frame(double t) {
    output_sample s = {t, poses, object_centres, NULL, 0, NULL};
    return output_frame_add(&s);
}

int world_run_start(int n, const options *o, const world_robots *all, uint32_t nominal_hz,
                    int physics_thread) {
    robots = all;
    n_robots = n;
    ir_range_mm = o->ir_range_mm;
    poses = allocate((size_t)n, sizeof *poses);
    object_centres = allocate((size_t)spec.n_objects, sizeof *object_centres);
    light_mv = allocate((size_t)n, sizeof *light_mv);
    reached_by = allocate((size_t)n, sizeof *reached_by);
    for (int i = 0; i < n; i++) light_mv[i] = -1;
    for (int k = 0; k < WORLD_STEPS_AHEAD; k++) {
        notes[k].leds = allocate((size_t)n, 3);
        notes[k].ir = allocate((size_t)n, sizeof *notes[k].ir);
    }
    /* Of the nominal clock, as world_run_after_window counts (robot 0's own
     * may run fast or slow). */
    step_cycles = (avr_cycle_count_t)llround(WORLD_STEP_S * nominal_hz);
    next_step = step_cycles;
    steps_noted = steps_seen = 0;
    world_stepper_start(physics, n, spec.n_objects, physics_thread);
    observe_start();
    if (o->out_dir == NULL) return 0;
    output_options out = {.dir = o->out_dir, .video = o->video, .quiet = o->quiet,
                          .ids = o->ids, .video_fps = o->video_fps, .video_speed = o->video_speed};
    if (output_open(&out, &spec) != 0) return -1;
    recording = 1;
    next_sample_s = spec.sample_period_s;
    end_s = o->seconds;
    note_leds(notes[0].leds);
    show_leds(notes[0].leds);
    for (int i = 0; i < n_robots; i++) robots->ir(i, &notes[0].ir[i]);
    if (sample(0.0, notes[0].ir) != 0 || (o->video && frame(0.0) != 0)) return -1;
    next_frame_s = output_next_frame_s();
    return 0;
}

/* The oldest step under way is over: the robots sense where it left
 * them, and its sample is taken. */
static void see_step(void) {
    const world_poses *seen = world_stepper_take();
    const step_notes *noted = &notes[steps_seen++ % WORLD_STEPS_AHEAD];
    for (int i = 0; i < n_robots; i++) {
        poses[i].x_mm = seen->robots[i].x_mm;
        poses[i].y_mm = seen->robots[i].y_mm;
        poses[i].heading_deg = seen->robots[i].heading_deg;
    }
    sense();
    if (!noted->sample_due && !noted->frame_due) return;
    for (int k = 0; k < spec.n_objects; k++) object_centres[k] = seen->objects[k];
    show_leds(noted->leds);
    if (noted->sample_due && sample(noted->t, noted->ir) != 0) sample_failed = 1;
    if (noted->frame_due && frame(noted->t) != 0) sample_failed = 1;
}

/* What the step ending at t will be sampled with, noted at t. */
static void note_step(double t) {
    step_notes *n = &notes[steps_noted++ % WORLD_STEPS_AHEAD];
    n->t = t;
    n->sample_due = recording && t + 1e-9 >= next_sample_s;
    if (n->sample_due) next_sample_s += spec.sample_period_s;
    n->frame_due = recording && t + 1e-9 >= next_frame_s && t < end_s - 1e-9;
    if (n->frame_due) next_frame_s = output_frame_after_s(t);
    if (n->sample_due || n->frame_due) note_leds(n->leds);
    if (n->sample_due)
        for (int i = 0; i < n_robots; i++) robots->ir(i, &n->ir[i]);
}

void world_run_after_window(avr_cycle_count_t end, uint32_t nominal_hz) {
    while (end >= next_step) {
        double t = (double)next_step / nominal_hz;
        world_stepper_prepare(t); /* while the steps before may still run */
        if (world_stepper_pending() == WORLD_STEPS_AHEAD) see_step();
        note_step(t);
        world_stepper_begin();
        next_step += step_cycles;
    }
}

void world_run_position(int index, double *x_mm, double *y_mm) {
    *x_mm = poses[index].x_mm;
    *y_mm = poses[index].y_mm;
}

int world_run_is_epuck(void) { return spec.robot_kind == WORLD_ROBOT_EPUCK; }

int world_run_is_native(void) { return spec.fidelity == WORLD_FIDELITY_NATIVE; }

/* The native mode when the controller is a native robot (as for
 * Kilobots, whatever the world says); a world that asks for it refuses
 * controllers built for the pipe mode. "qemu" runs e-puck2 images in
 * QEMU, and only those; the pipe mode refuses one. NULL after a message. */
static const epuck_controllers *controllers_for(const options *o) {
    if (o->robots > 0 && native_is_robot(o->robot_elf[0])) return &native_epucks;
    int images = 1;
    for (int i = 0; i < o->robots; i++) {
        if (epuck_link_is_epuck2_image(o->robot_elf[i])) continue;
        images = 0;
        if (spec.fidelity != WORLD_FIDELITY_QEMU) break;
        fprintf(stderr, "openswarm-sim: %s asks for \"fidelity\": \"qemu\", and robot %d's controller %s "
                        "is not an e-puck2 image (an ARM ELF): give the app's image for the world "
                        "(`openswarm build --qemu`: build/epuck_world-qemu/<app>.elf), or drop \"fidelity\" "
                        "from the world to run a host program\n", spec.path, i, o->robot_elf[i]);
        return NULL;
    }
    if (spec.fidelity == WORLD_FIDELITY_QEMU) return &epuck_qemu;
    if (o->robots > 0 && images) {
        fprintf(stderr, "openswarm-sim: %s is an e-puck2 image, which runs under QEMU: give the world "
                        "\"fidelity\": \"qemu\", or the app's host program (`openswarm build`: "
                        "build/epuck_world/<app>)\n", o->robot_elf[0]);
        return NULL;
    }
    if (spec.fidelity != WORLD_FIDELITY_NATIVE) return &epuck_pipes;
    fprintf(stderr, "openswarm-sim: %s asks for \"fidelity\": \"native\", and %s is a controller "
                    "for the pipe mode (a program): give the app built for the host's native mode "
                    "(`openswarm build --native`: build/epuck_world-native/<app>.so), or drop "
                    "\"fidelity\" from the world\n", spec.path, o->robot_elf[0]);
    return NULL;
}

int world_run_epucks(const options *o) {
    const epuck_controllers *where = controllers_for(o);
    if (where == NULL) {
        world_destroy(physics);
        world_spec_free(&spec);
        return EXIT_USAGE;
    }
    int status = epuck_world_run(o, &spec, physics, where);
    world_destroy(physics);
    world_spec_free(&spec);
    return status;
}

int world_run_finish(void) {
    while (world_stepper_pending() > 0) see_step();
    world_stepper_stop();
    if (interrupt_caught()) output_quieten(); /* interrupt_finish names the files */
    int status = recording ? output_close() : 0;
    if (sample_failed) status = -1;
    world_destroy(physics);
    world_spec_free(&spec);
    return status;
}
