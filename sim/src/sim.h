/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/*
 * openswarm-sim: runs robots' firmware ELFs, cycle-exactly, in simavr.
 *
 * Conventions shared with the firmware (ports/kilobot/include/openswarm/kilobot_sim.h):
 *   GPIOR1  console: each byte written is a character, '\n' ends a line;
 *           0x01 starts a kernel fault record: the fault, then the thread
 *   UART0   the robot's debug serial port, printed like the console
 *   GPIOR0  exit status, read when the firmware stops (SLEEP with
 *           interrupts disabled)
 *   GPIOR2  marker: with --marks, every change of its value is printed
 *           with the exact cycle, for cycle-exact measurements
 */
#ifndef OPENSWARM_SIM_H
#define OPENSWARM_SIM_H

#include <stdint.h>
#include <stdio.h>

#include <sim_avr.h>
#include <sim_vcd_file.h>

#include "air/ir_distance_error.h"

#define GPIOR0_ADDR 0x3E
#define GPIOR1_ADDR 0x4A
#define GPIOR2_ADDR 0x4B
#define MAX_WATCHED_IRQS 8
#define MAX_ROBOTS 10000 /* more is likely a typo; memory is the only limit */
#define MAX_FIRMWARE 64
/* Robots run in lockstep windows this many cycles long; an IR edge reaches
 * its receivers exactly this long after it left (air/ir_channel.c). */
#define IR_LATENCY_CYCLES 64
/* A Kilobot's clock: a firmware without an MCU record runs at it, and a
 * world without robots counts its time in it. */
#define KILOBOT_CLOCK_HZ 8000000u
#define MAX_OHC_MESSAGES 16

enum { EXIT_USAGE = 2, EXIT_CRASH = 3, EXIT_TIMEOUT = 4, EXIT_BOOTLOADER = 5, EXIT_FAULT = 6,
       EXIT_HANG = 7, EXIT_WARNINGS = 8 };

/* Where a Kilobot's IR bootloader starts (a byte address): the ATmega328P's
 * 4 KB boot section. The overhead controller's BOOT message jumps there. */
#define KILOBOT_BOOTLOADER_ADDRESS 0x7000

/* A system message the overhead controller broadcasts at a time. */
typedef struct ohc_message {
    double seconds;
    uint8_t type;
    uint8_t data[9];
} ohc_message;

/* Where the robots stand, in millimetres. */
typedef struct placement {
    int has_positions; /* 0: every pair distance_mm apart */
    int distance_mm;
    double *x_mm, *y_mm; /* has_positions: one per robot */
} placement;

typedef struct options {
    const char *elves[MAX_FIRMWARE]; /* robot k runs elves[k], the last one the rest */
    int n_elves;
    double seconds;
    int robots;
    int quiet;
    int expect_stop;
    int allow_faults; /* kernel faults do not fail the run */
    int strict;       /* the warnings at the end fail the run (EXIT_WARNINGS) */
    double mask_limit_ms; /* interrupts masked longer than this fail the run; 0: never */
    int main_stack;     /* print each robot's main stack's worst use */
    int timestamps;     /* console and serial lines begin with their time */
    int marks;
    int profile;        /* cycles by function, printed at the end */
    int watched[MAX_WATCHED_IRQS];
    int n_watched;
    int trace;
    const char *trace_csv;
    const char *console_csv; /* --console-csv FILE: every robot's console lines */
    int gdb_port;       /* 0: no debugger */
    const char *vcd;
    int light_mv, voltage_mv, temperature_mv; /* ADC inputs, -1: 0 V */
    int charging;       /* on the charger: its status output (PD0) low */
    int uid;            /* first robot's id; -1: EEPROM left erased (one robot) */
    placement place;    /* --distance (default), --line or --positions */
    const char *positions; /* --positions FILE, NULL: not given */
    int ir_range_mm;    /* a robot hears senders this close or closer */
    int ir_log;         /* print every frame on the air, decoded */
    double clock_spread_pct; /* robots' clocks differ by up to this, either way */
    double ir_loss_pct;      /* a frame's chance to be lost at the range's edge */
    ir_distance_error ir_distance; /* the distance estimates' error: a world's "ir" (none without) */
    uint64_t ir_loss_seed;   /* the loss draws': from a world's seed (0 without a world) */
    ohc_message ohc[MAX_OHC_MESSAGES];
    int n_ohc;
    int calibration[4]; /* turn left, turn right, straight left, straight right; -1: erased */
    const char **robot_elf; /* per robot, when a world names firmware (else elves) */
    unsigned given;     /* GIVEN_* bits: what the command line set */
    const char *world;  /* --world FILE: robots move in it (world/) */
    const char *out_dir; /* --out DIR: what a run in a world leaves (output/) */
    int video;          /* --video: also video.mp4 */
    double video_fps, video_speed; /* --video-fps, --video-speed; 0: the defaults (25, 1) */
    int ids;            /* --ids: final.png and the video number the robots */
    int progress;       /* a status line on stderr while it runs: -1 auto, 0 no, 1 yes */
    int threads;        /* --threads: 0 picks by the machine and the swarm */
    struct fault_spec *faults; /* --faults (faults/faults.h); NULL: none */
    const char *fault_log;     /* --fault-log FILE */
    double counters_period;    /* --counters PERIOD: seconds; 0: at the end only; -1: never */
    int no_loop_skip;          /* --no-loop-skip: every repeat of a loop run (loop_skip.h) */
} options;

/* What the command line set, for what a world file may also set. */
enum {
    GIVEN_TIME = 1, GIVEN_ROBOTS = 2, GIVEN_PLACEMENT = 4, GIVEN_UID = 8, GIVEN_CALIBRATION = 16,
    GIVEN_IR_RANGE = 32, GIVEN_IR_LOSS = 64, GIVEN_CLOCK_SPREAD = 128, GIVEN_LIGHT = 256
};

/* options.c */
int parse_options(int argc, char **argv, options *o);
int options_check_robots(options *o);
/* --help's text (options_usage.c). */
void options_usage(FILE *out);
/* -1 after saying which output would overwrite which input (options_outputs.c). */
int outputs_apart_from_inputs(const options *o);
const char *firmware_of(const options *o, int index);

/* A robot's clock error as a fraction of --clock-spread (main.c), -1..1. */
double robot_clock_error(int index, int n);

/* placement.c: --distance, --line SPACING, --positions FILE (robots is
 * set to the file's count; it must match when robots_given) */
void placement_all_at(placement *p, int distance_mm);
int placement_line(placement *p, int robots, const char *spacing_text);
int placement_file(placement *p, const char *path, int *robots, int robots_given);
double placement_distance(const placement *p, int a, int b);
/* The same, as the IR channel asks it (ctx: the placement). */
double placement_distance_of(int a, int b, void *ctx);

/* A robot's finished console and serial lines not yet in --console-csv,
 * as CSV rows: the robot's thread adds them, the main thread writes them
 * after each window (console.c). */
typedef struct console_rows {
    char *text;
    size_t len, room;
    int failed; /* out of memory: reported once, at the end */
} console_rows;

/* A line-buffered text output of one robot (its console or serial port). */
typedef struct console {
    char prefix[24];
    int index;            /* the robot's */
    console_rows *rows;   /* --console-csv: its lines go there too; NULL: no */
    const avr_t *avr;     /* its robot's, for the time of a line */
    int timestamps;       /* each line begins with its time, as trace lines do */
    char line[256];
    size_t len;
    int quiet;            /* lines dropped; kernel faults still reported */
    uint8_t record[2];    /* a kernel fault record being received */
    int record_left;      /* its bytes still to come */
    unsigned faults;      /* kernel faults reported */
    int overrun_pending;  /* a handler past its limit, to be named (code_place.c) */
    unsigned from_interrupt;   /* characters written from an interrupt handler */
    double from_interrupt_at;  /* the first one's time */
    /* Thread names the firmware told (kilobot_sim.h: 0x02, pid, name, 0),
     * by the pid's slot (its low 4 bits); the pid they were told for. */
    char thread_name[16][32];
    uint8_t thread_pid[16];
    int naming;           /* 0: no; 1: the pid comes next; 2: the name's characters */
    uint8_t naming_pid;
    size_t naming_len;
} console;

/* Told of every motor duty change at its cycle (the world moves the robot). */
typedef void (*motors_changed_fn)(void *ctx, int robot, uint8_t left, uint8_t right,
                                  avr_cycle_count_t cycle);

/* What the robot shows: LED colour and motor duty, reported once settled. */
typedef struct robot_trace {
    motors_changed_fn on_motors;
    void *on_motors_ctx;
    avr_t *avr;
    int index;
    const char *prefix;
    int print;
    FILE *csv;
    uint8_t ddrc, ddrd;
    uint8_t pwm[2];          /* left (OC2A), right (OC2B) */
    int shown_rgb;           /* last reported, -1 before the first */
    int shown_pwm[2];
    avr_cycle_count_t burst; /* cycle of the first unreported change, 0: none */
} robot_trace;

typedef struct watched_irq {
    avr_t *avr;
    int vector;
    int robot; /* -1 with one robot */
} watched_irq;

/* A timer's event, out of simavr's schedule while the robot is powered
 * down, with the cycles it had left. */
typedef struct frozen_event {
    avr_cycle_timer_t fn;
    void *param;
    avr_cycle_count_t left;
} frozen_event;

#define MAX_FROZEN_EVENTS 16

/* power_down.c: a robot asleep in power-down mode, its timers stopped. */
typedef struct power_down {
    int asleep;
    avr_cycle_count_t since; /* the cycle it went to sleep */
    frozen_event events[MAX_FROZEN_EVENTS];
    int n_events;
} power_down;

/* stack_watch.c: the stack pointer below the lowest address its stack
 * allows - above a thread stack's guard, above the RAM the image reserves -
 * is an overflow, caught at the instruction. The kernel's guard and the
 * main stack's paint see only the bytes a frame writes: a frame that
 * skips them overwrites what lies below unseen. Each stack's lowest SP is
 * kept too: its worst use, frames reserved but never written included. */
#define MAX_SWITCH_CODE 4
#define MAX_WATCHED_STACKS 17 /* main's and 16 threads' */
typedef struct watched_stack {
    uint16_t floor;  /* the lowest SP it allows */
    uint16_t lowest; /* its lowest SP yet */
} watched_stack;
typedef struct stack_watch {
    const char *elf; /* its firmware, to name the code that overflowed */
    uint16_t mark; /* SP below this is looked at: the lowest yet of the stack it is on */
    watched_stack stacks[MAX_WATCHED_STACKS]; /* [0]: main()'s, floor _end - 1; 0: unwatched */
    int n_stacks, on;                         /* on: the one SP is on */
    uint16_t pool, pool_end, block; /* the kernel's os_stack_pool and its block size */
    /* The code that moves SP from one stack to another (the port's switch.S):
     * SP is not checked there, and the stack is found again after it. */
    uint32_t switch_code[MAX_SWITCH_CODE][2];
    int n_switch_code;
    uint32_t switch_lo, switch_hi;   /* around all of it */
    uint32_t thread_start[2];        /* port_thread_start: a new thread's first instructions */
    uint32_t switch_pc;              /* the last instruction ran there, at this address; 0: no */
    enum { STACKS_KEPT, THREAD_STACK_OVERFLOWED, MAIN_STACK_OVERFLOWED } overflowed; /* reported */
} stack_watch;

/* handler_watch.c: which instructions ran (a bit per flash word), and
 * where the kernel keeps its subscriptions (data-space addresses), to
 * name at the end every handler subscribed and never called. */
typedef struct handler_watch {
    uint8_t *ran; /* NULL: not watched (no OpenSwarm kernel in the image) */
    char *elf;    /* the firmware's path, our copy */
    uint32_t subs, subs_size, subs_end;
    uint32_t bound;      /* the kernel's trampoline for bindings, a byte address */
    uint32_t library[3]; /* the kernel's and kilolib's own handlers, byte addresses */
} handler_watch;

#define MAX_REGISTER_STORE_CODE 8
typedef struct robot {
    int index;
    avr_t *avr;
    console console, serial;
    console_rows console_rows; /* both's lines for --console-csv */
    robot_trace trace;
    watched_irq watches[MAX_WATCHED_IRQS];
    avr_vcd_t vcd;
    int vcd_open;
    int state; /* of its last avr_run */
    power_down power_down;
    /* Asleep with nothing due before this cycle of the nominal clock: not
     * run in windows that end earlier. 0: run it. Whatever registers a timer
     * on a sleeping robot from outside (an IR edge) sets it back to 0. */
    avr_cycle_count_t doze_until;
    int wake_registered; /* its window-end timer is set */
    /* loop_skip.h: the instruction where the state is compared with the
     * last visit's (LOOP_SKIP_NO_ANCHOR: none), and the rest (NULL: off). */
    uint32_t skip_anchor;
    struct loop_skip *skip;
    uint16_t main_stack_floor; /* the RAM the image reserves ends here; 0: unmeasured */
    avr_cycle_count_t masked_since; /* interrupts off since this cycle; 0: they are on */
    int hung;                  /* reported: interrupts masked past the limit */
    stack_watch stack_watch;
    handler_watch handler_watch;
    /* register_store_watch.c: reported, a store through a pointer into
     * r0-r31; and the code that does so on purpose (avr-libc's EEPROM
     * reads, which load their result into r22-r25 that way). */
    int register_store_watched, stored_to_register;
    uint32_t register_store_code[MAX_REGISTER_STORE_CODE][2];
    int n_register_store_code;
    /* invalid_opcode.c: stopped at an invalid opcode, which, and where */
    int at_invalid_opcode;
    uint16_t invalid_opcode;
    uint32_t invalid_opcode_pc;
    /* Powered off (--faults brownout) until this cycle of the nominal
     * clock: not run, deaf to IR. 0: powered. */
    avr_cycle_count_t off_until;
    /* Where its firmware keeps the counters --counters reads (data-space
     * addresses, 0: none), from the ELF's symbols when it was loaded: a
     * file rebuilt during the run must not move them. */
    struct counter_symbols {
        uint32_t kernel, kernel_size;
        uint32_t ir, ir_size;
        uint32_t stack_pool, stack_pool_size; /* the kernel's os_stack_pool */
    } counters;
} robot;

/* firmware.c: check and load an ELF into a new simulated MCU */
int firmware_check(const char *path);
avr_t *firmware_load(const char *path);

/* firmware_symbols.c: each(name (NULL if unreadable), value, size, type
 * (STT_*), ctx) for every symbol of the ELF at path; -1 if it has none to
 * read (a .hex). */
typedef void (*firmware_symbol_fn)(const char *name, uint32_t value, uint32_t size, int type, void *ctx);
int firmware_symbols(const char *path, firmware_symbol_fn each, void *ctx);
/* The same into answer (size bytes, cleared first), unless *read_path is
 * path already: robots that share a firmware file share the answer. */
void firmware_symbols_once(const char *path, const char **read_path, firmware_symbol_fn each,
                           void *answer, size_t size);
/* name is wanted, or wanted.lto_priv.N as link-time optimisation renames a
 * static. */
int symbol_named(const char *name, const char *wanted);
/* Data-space addresses in the ELF are offset by this (avr-libc's scripts). */
#define AVR_DATA_OFFSET 0x800000u

/* main_stack.c: the main stack's worst use, from a pattern painted over
 * its room at load; report prints it (print) and says if it overflowed
 * (returns 1). */
void main_stack_paint(robot *r, const char *elf_path);
/* Bytes of the main stack used at worst (0 if unmeasured) and its room. */
unsigned main_stack_worst(const robot *r, unsigned *room);
/* thread_stacks.c: the kernel's thread stacks' worst use, by address (at
 * most room of them), from its stack pool at data address pool, size bytes
 * (size 0: none): how many, or -1 if there is no pool. */
typedef struct thread_stack {
    unsigned used, room;
} thread_stack;
int thread_stacks_read(const robot *r, uint32_t pool, uint32_t size, thread_stack *out, int room);
/* Does a thread stack's guard (the kernel's OS_STACK_GUARD) start at ram[i],
 * all of it before end? */
#define STACK_GUARD_BYTES 4
int stack_guard_at(const uint8_t *ram, uint32_t i, uint32_t end);
/* firmware_counters.c: --counters, robot r's kernel and IR counters and
 * main stack, read from its RAM by symbol, as one line on stdout; the
 * symbols read as the firmware is loaded (firmware_counters_locate). */
void firmware_counters_locate(robot *r, const char *elf_path);
void firmware_counters_print(const robot *r, double seconds);
/* The kernel's counters (os_stats: twelve 16-bit counters and the event
 * queue's peak byte) and the IR driver's (kilobot_ir_counters: seven)
 * from their bytes, as " name=value" each, in either mode; NULL: the
 * firmware has none; layout_known 0: they are not laid out so. */
void firmware_counters_print_kernel(FILE *out, const uint8_t *bytes, int layout_known);
void firmware_counters_print_ir(FILE *out, const uint8_t *bytes, int layout_known);
/* Robot r's firmware IR counters now (kilobot_ir_stats' seven, in order):
 * 1, or 0 when its firmware keeps none (or another layout). */
#define KILOBOT_IR_COUNTERS 7
int firmware_ir_counters(const robot *r, uint16_t out[KILOBOT_IR_COUNTERS]);
int main_stack_report(const robot *r, int print);

/* warning_groups.c: the end-of-run warnings, noted robot by robot (-1: a
 * run of one robot) as the text after "warning: ", then printed once per
 * text with the robots that gave it ("[robots 0-999] warning: ..."); how
 * many lines. */
void warning_note(int robot_index, const char *format, ...) __attribute__((format(printf, 2, 3)));
int warnings_print(void);

/* The robots whose set-up the warnings' fixes name. */
typedef enum robot_kind { ROBOT_KILOBOT, ROBOT_EPUCK } robot_kind; /* as kernel_losses.h's */

/* event_names.c: "EV_QUIET (event 10)", "KILOBOT_EVENT_LIGHT (event 6)", or
 * "event 12" when the event has no name known (an app's own number); the
 * app's names are read from firmware's section .openswarm.events. Into
 * out, which is returned. */
const char *event_name(const char *firmware, robot_kind kind, unsigned id, char *out, size_t size);

/* firmware_warnings.c: at the end of a run, what robot r's firmware lost
 * or refused (its kernel's counters) and printed from an interrupt, as
 * warnings noted with the fix; how many. */
int firmware_warnings_report(const robot *r);
/* The same for a kernel's counters (os_stats' twelve, in order) wherever
 * they were read from (the native mode: the host's), for robot (-1: the
 * only one) of that kind. */
#define OS_STATS_COUNTERS 12
int kernel_loss_warnings(int robot_index, robot_kind kind, const uint16_t *counters);
/* With --strict, warnings (a count) fail the run: said, and 1. */
int warnings_fail_run(int warnings, const options *o);

/* handler_watch.c: at load, where robot r's kernel keeps its
 * subscriptions; at every instruction, that it ran; at the end, each
 * handler subscribed and never called as a warning; how many. */
void handler_watch_attach(robot *r, const char *elf_path);
int handler_watch_report(const robot *r, int robot_index);
/* The kernel's and kilolib's own handlers, by a function's name: never
 * warned of (the app did not subscribe them). */
int handler_watch_library_name(const char *name);
/* The warning of a handler never called, as each mode words it: the
 * handler's place in the sources, its event's name, its thread, the run's
 * simulated seconds. */
void handler_never_called_note(int robot_index, const char *place, const char *event, unsigned pid,
                               double seconds);
static inline void handler_watch_step(robot *r) {
    uint8_t *ran = r->handler_watch.ran;
    uint32_t pc = r->avr->pc;
    if (ran != NULL && pc <= r->avr->flashend) ran[pc >> 4] |= (uint8_t)(1u << ((pc >> 1) & 7u));
}

/* code_place.c: "stuck, main.c:17 (PC 0x1a2)", where a byte address is in
 * the sources of the ELF (avr-addr2line), as far as it can tell, in out. */
const char *code_place(const char *elf, uint32_t pc, char *out, size_t size);
/* The same for a host shared object (a native robot) and an offset into
 * it (addr2line): "on_quiet, main.c:17", or the function alone, or the
 * offset; the function's name alone into function (function_size). */
const char *host_code_place(const char *so, uint64_t offset, char *out, size_t size, char *function,
                            size_t function_size);
/* After a window: a handler reported past its limit is named by where
 * robot r runs now (the tick that reported it has returned into it). */
void fault_place_after_window(robot *r, const char *elf);

/* interrupt_watch.c: a robot running with interrupts masked for more than
 * limit_ms (0: never reported) is reported once and marked hung. Each
 * instruction's I flag is noted (inline: it runs at every instruction), so
 * one instruction with interrupts on - a reti, a sei - restarts the count,
 * wherever the window ends fall. */
void interrupt_watch_check(robot *r, double limit_ms);
static inline void interrupt_watch_step(robot *r) {
    if (r->avr->sreg[S_I])
        r->masked_since = 0;
    else if (r->masked_since == 0)
        r->masked_since = r->avr->cycle ? r->avr->cycle : 1;
}

void stack_watch_attach(robot *r, const char *elf_path);
/* After a reset: main()'s stack again. */
void stack_watch_reset(robot *r);
void stack_watch_found_stack(robot *r);
void stack_watch_below(robot *r);
/* The main stack's worst use by its lowest SP (0: unwatched). */
unsigned stack_watch_main_used(const robot *r);
/* The lowest byte the thread stack whose guard starts at data address
 * guard has used by its lowest SP; 0: not seen. */
uint32_t stack_watch_thread_deepest(const robot *r, uint32_t guard);
static inline int stack_watch_in_switch_code(const stack_watch *w, uint32_t pc) {
    if (pc < w->switch_lo || pc >= w->switch_hi) return 0;
    for (int i = 0; i < w->n_switch_code; i++)
        if (pc >= w->switch_code[i][0] && pc < w->switch_code[i][1]) return 1;
    return 0;
}
/* Every instruction: an SP comparison (out of line only at a new depth of
 * the main stack or below a thread stack's floor), and a look for the
 * stack SP is on when the code that moves it between stacks has run. */
static inline void stack_watch_step(robot *r) {
    stack_watch *w = &r->stack_watch;
    if (w->n_stacks == 0) return;
    if (stack_watch_in_switch_code(w, r->avr->pc)) {
        w->switch_pc = r->avr->pc;
    } else if (w->switch_pc != 0) {
        stack_watch_found_stack(r);
    } else if ((uint16_t)(r->avr->data[R_SPL] | r->avr->data[R_SPH] << 8) < w->mark) {
        stack_watch_below(r);
    }
}

/* register_store_watch.c: a store through a pointer (X, Y or Z: 0, 1, 2)
 * to a data address below 0x20, the CPU's registers. */
void register_store_watch_attach(robot *r, const char *elf_path);
void register_store_report(robot *r, unsigned pointer, unsigned address);
/* The pointer register (X r27:r26, Y r29:r28, Z r31:r30) of a store
 * instruction, its address as the store uses it. */
static inline unsigned pointer_at(const avr_t *avr, unsigned pointer) {
    return avr->data[26u + 2u * pointer] | avr->data[27u + 2u * pointer] << 8;
}
/* Before each instruction: is it ST or STD, and below 0x20 where it
 * stores? ST/STD Y+q, Z+q: 10q0 qq1r rrrr bqqq (b: Y); ST with X, or with
 * Y or Z moving: 1001 001r rrrr xxxx (1, 2: Z+, -Z; 9, A: Y+, -Y; C, D, E:
 * X, X+, -X; 0 is STS, F is PUSH). */
static inline void register_store_check(robot *r) {
    const avr_t *avr = r->avr;
    uint16_t op = (uint16_t)(avr->flash[avr->pc] | avr->flash[avr->pc + 1] << 8);
    unsigned pointer, offset = 0, before = 0;
    if ((op & 0xD200u) == 0x8200u) {
        pointer = op & 0x8u ? 1u : 2u;
        offset = (op & 0x7u) | ((op >> 7) & 0x18u) | ((op >> 8) & 0x20u);
    } else if ((op & 0xFE00u) == 0x9200u) {
        static const int8_t kind[16] = {-1, 2, 2, -1, -1, -1, -1, -1, -1, 1, 1, -1, 0, 0, 0, -1};
        static const uint8_t decrements[16] = {[2] = 1, [10] = 1, [14] = 1};
        int k = kind[op & 0xFu];
        if (k < 0) return;
        pointer = (unsigned)k;
        before = decrements[op & 0xFu];
    } else {
        return;
    }
    unsigned address = (pointer_at(avr, pointer) - before + offset) & 0xFFFFu;
    if (address < 0x20u) register_store_report(r, pointer, address);
}

/* profile.c: --profile */
int profile_load(const char *elf_path);
void profile_charge(uint32_t pc, int was_asleep, uint64_t cycles);
void profile_print(int robots);

/* console.c */
void console_attach(robot *r, int quiet, int timestamps, const char *prefix, int csv);
/* --console-csv FILE: opened with its header (time_s,robot,line), or NULL
 * after saying why; a row; the rows robots kept since the last call, in
 * robot order (the same file on any number of threads); closed, -1 if
 * anything was lost. */
FILE *console_csv_open(const char *path);
void console_csv_row(FILE *f, double time_s, int index, const char *line);
void console_csv_write(FILE *f, robot *robots, int n);
int console_csv_close(FILE *f, const char *path, robot *robots, int n);
/* A kernel fault's name (a sys_fault), as the consoles print it. */
const char *kernel_fault_name(uint8_t fault);
/* After a reset: a kernel fault record or thread name under way is dropped. */
void console_reset(robot *r);

/* robot_trace.c */
void trace_attach(robot *r, int print, FILE *csv);
void trace_flush(robot *r);
/* After a reset: the LED dark, the motors still (as the chip's pins). */
void trace_reset(robot *r);
/* The LED's colour now, each channel 0..3. */
void trace_led(const robot *r, uint8_t rgb[3]);

/* The Kilobot's analog inputs: simavr converts millivolts against AVcc. */
#define KILOBOT_AVCC_MV 3300

/* kilobot_board.c: what the robot's EEPROM and sensors hold: uid -1
 * leaves the EEPROM's uid erased, a calibration duty -1 its byte. */
void board_configure(avr_t *avr, const options *o, int uid, const int calibration[4]);
/* What a robot's EEPROM holds before it runs, as write(ctx, address,
 * bytes, n) calls: its calibration duties (-1: left as they are), the
 * distance tables, its uid (-1: left as it is). */
typedef void (*eeprom_write_fn)(void *ctx, uint16_t address, const uint8_t *bytes, uint32_t n);
void kilobot_eeprom_fill(eeprom_write_fn write, void *ctx, int uid, const int calibration[4]);
/* An eeprom_write_fn into the EEPROM of the avr_t ctx. */
void board_eeprom_write(void *avr, uint16_t address, const uint8_t *bytes, uint32_t n);
/* After a reset (simavr clears the I/O registers): the pins the board
 * drives read as they did. */
void board_pins_again(avr_t *avr);
/* The calibration blank, as a robot never calibrated: OSCCAL, the motor
 * duties and the distance tables read 0xFF (the uid stays); either mode's
 * EEPROM, through write. */
void kilobot_eeprom_erase_calibration(eeprom_write_fn write, void *ctx);
/* Data memory and flash widened to every address an instruction can form
 * (board/wide_memories.c says why); -1 when out of memory. */
int board_widen_memories(avr_t *avr);

/* power_down.c: SLEEP in power-down stops Timer0/1/2; call around each avr_run.
 * The tests are inline: they run at every instruction, and a call each
 * way cost a seventh of the simulator's speed. */
#define SMCR_ADDR 0x53
#define SMCR_MODE_MASK 0x0F          /* SM2:0 and SE */
#define SMCR_POWER_DOWN_ENABLED 0x05 /* SM = 010, SE = 1 */
#define SLEEP_OPCODE 0x9588
void power_down_freeze(robot *r);
void power_down_thaw(robot *r);

/* Whether the instruction at the PC lies in flash. A return through a
 * stack overwritten or freed too far jumps anywhere (a thread's paint,
 * 0xE7E7: byte 0x1CFCE, past 32 KB); simavr 1.6 reads there before its own
 * bounds check, as the watches below would: test this first. */
static inline int pc_in_flash(const avr_t *avr) { return avr->pc + 1u <= avr->flashend; }

static inline int at_sleep_instruction(const avr_t *avr) {
    return (avr->flash[avr->pc] | avr->flash[avr->pc + 1] << 8) == SLEEP_OPCODE;
}

static inline void power_down_before_step(robot *r) {
    if ((r->avr->data[SMCR_ADDR] & SMCR_MODE_MASK) == SMCR_POWER_DOWN_ENABLED && !r->power_down.asleep &&
        r->state == cpu_Running && at_sleep_instruction(r->avr))
        power_down_freeze(r);
}

static inline void power_down_after_step(robot *r) {
    if (r->power_down.asleep && r->state != cpu_Sleeping) power_down_thaw(r);
}

/* analog_noise.c: every conversion reads its input plus gaussian noise of
 * sd_counts ADC counts, from the robot's own sequence (seed). */
void analog_noise_attach(robot *r, uint64_t seed, double sd_counts);

/* adc_trigger.c: ADC conversions started by the analog comparator (ADTS 001) */
void adc_trigger_attach(avr_t *avr);

/* measure.c: markers and interrupt timestamps */
int measure_attach(robot *r, const options *o);

/* The Kilobot IR wire format (ports/kilobot/src/devices/ir.c), as the
 * channel, the overhead controller and --ir-log use it: slots of one bit
 * time; a start pulse, the stop pulse 9 slots later, then 12 bytes of 10
 * slots each (a start bit, 8 data bits LSB first, a stop bit); a flash lights
 * a receiver's comparator input to IR_LIT_MV. */
#define IR_BIT_CYCLES 269
#define IR_HEADER_SLOTS 10
#define IR_FRAME_BYTES 12
#define IR_FRAME_SLOTS (IR_HEADER_SLOTS + IR_FRAME_BYTES * 10)
#define IR_CRC_BYTES 10 /* the CRC covers the data and the type; it fills the last two */
#define IR_LIT_MV 1000

/* ir_frame.c: a frame's CRC-16 CCITT (seed 0xFFFF) over its first
 * IR_CRC_BYTES bytes, stored little-endian after them */
uint16_t ir_frame_crc(const uint8_t *bytes);

/* ir_channel.c: every robot hears the IR LED of every other within range */
/* loss_pct: the chance, in percent, that a frame is lost to a receiver at
 * the range's edge; closer, it falls with the distance squared; each
 * sender draws its losses from its own stream of loss_seed. distance: the
 * error of the distance the receivers read (NULL: none). */
void ir_channel_attach(robot *all, int n, int range_mm, double loss_pct, uint64_t loss_seed,
                       const ir_distance_error *distance);
/* How far apart robots a and b are, in mm. */
typedef double (*ir_distance_fn)(int a, int b, void *ctx);
/* Who reaches whom, from where the robots are now; again when they move. */
void ir_channel_place(ir_distance_fn distance, void *ctx);
/* Between two lockstep windows: the edges sent in the last one go to their
 * receivers, due latency_cycles (nominal clock) after they left. */
void ir_channel_hand_over(uint32_t latency_cycles);
/* Robot index was reset or lost its power: the edges on their way to it
 * are dropped, and the faults it was sending end. */
void ir_channel_robot_reset(int index);
/* The receivers sender reaches (up to room of them), and their count. */
int ir_channel_links(int sender, int *receivers, int room);
/* Frames from robots in range since the start that reached receiver (its
 * comparator saw them: a collision or an added fault may still break
 * them) and those the channel lost on the way (--ir-loss). */
void ir_channel_counts(int receiver, uint64_t *heard, uint64_t *lost_channel);
/* ir_log.c: --ir-log, the frames on the air decoded by the wire format */
void ir_log_enable(int robots);
int ir_log_enabled(void);
/* A rising flash of from's IR LED; in_range names the robots it reaches. */
void ir_log_flash(const robot *from, avr_cycle_count_t cycle, const char *in_range);

/* The readings that model, for the calibration tables a robot keeps. */
int ir_high_gain_reading(int mm);
int ir_low_gain_reading(int mm);

/* overhead_controller.c: system messages broadcast at given times */
int ohc_parse(const char *text, ohc_message *m);
/* The frame m is on the wire: its data, its type, the CRC (both modes'). */
void ohc_frame(const ohc_message *m, uint8_t frame[IR_FRAME_BYTES]);
void ohc_attach(robot *all, int n, const options *o);
/* After robot r's reset: its messages to come are scheduled again. */
void ohc_robot_reset(robot *r);


/* debug.c: avr-gdb and GTKWave */
int debug_attach(robot *r, const options *o);
/* -1 after a message if the --vcd file could not be written. */
int debug_detach(robot *r);

/* written.c: flush f (and close it when close_it), what the run wrote as
 * what ("--trace-csv FILE", "the standard output"); -1 after a message
 * naming it and why if any write to it failed. */
int written_close(FILE *f, const char *what, int close_it);
/* fflush(stdout), keeping why it failed for written_close. */
void stdout_flush(void);

/* inputs.c: 0 if path is a regular file (or is not there: its reader
 * says so); else -1 after "WHAT PATH is a FIFO ..., not a regular file:
 * FIX". Checked before opening it: open() of a FIFO blocks. */
int input_is_regular(const char *what, const char *path, const char *fix);

#endif
