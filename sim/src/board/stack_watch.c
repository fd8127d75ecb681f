/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The stack pointer against the lowest address its stack allows (sim.h's
 * stack_watch). main() starts on the main stack, which may go down to the
 * RAM the image reserves (_end). The OpenSwarm kernel's threads run on
 * stacks carved from os_stack_pool in blocks, each with its guard at its
 * lowest address (kernel/src/stack_pool.c); a thread may go down to just
 * above its guard. SP moves from one stack to another only in the port's
 * switch code (ports/kilobot/src/switch.S): after it has run, the stack SP
 * is now on is found again - the main stack, or the guard at the nearest
 * block start below SP. Anywhere else, SP below that floor is an overflow,
 * reported once, at the instruction that made it, and the run fails as on
 * a kernel fault. Each stack's lowest SP is kept too: its worst use
 * (--main-stack, --counters, openswarm size), frames reserved but never
 * written included, which the paint the kernel and the simulator lay
 * cannot show. The compiler moves SP in two halves (SPH, SREG, SPL): the
 * half-written value is not judged. */
#include <string.h>

#include "sim.h"

#define SPL_IO 0x3D
#define SREG_IO 0x3F

static const char *const switch_code_names[] = {"port_switch", "port_thread_start",
                                                "port_call_on_system_stack"};
enum { THREAD_START = 1 }; /* port_thread_start's place above */
#define N_SWITCH_CODE (sizeof switch_code_names / sizeof switch_code_names[0])

/* What the watch needs of an image, read once per firmware file. */
typedef struct image_stacks {
    uint32_t end;               /* _end, a data-space address; 0: none */
    uint32_t pool, pool_size;   /* os_stack_pool's */
    uint32_t block;             /* os_stack_block_bytes (an absolute symbol); 0: none */
    uint32_t code[N_SWITCH_CODE][2];
} image_stacks;

static void note_symbol(const char *name, uint32_t value, uint32_t size, int type, void *ctx) {
    (void)type;
    image_stacks *s = ctx;
    if (name == NULL) return;
    if (strcmp(name, "_end") == 0 && s->end == 0) s->end = value;
    if (symbol_named(name, "os_stack_pool") && value >= AVR_DATA_OFFSET) {
        s->pool = value - AVR_DATA_OFFSET;
        s->pool_size = size;
    }
    if (strcmp(name, "os_stack_block_bytes") == 0) s->block = value;
    for (size_t i = 0; i < N_SWITCH_CODE; i++)
        if (strcmp(name, switch_code_names[i]) == 0 && size != 0) {
            s->code[i][0] = value;
            s->code[i][1] = value + size;
        }
}

static image_stacks stacks_of(const char *elf_path) {
    static const char *read_path;
    static image_stacks stacks;
    firmware_symbols_once(elf_path, &read_path, note_symbol, &stacks, sizeof stacks);
    return stacks;
}

static uint16_t stack_pointer(const avr_t *avr) { return (uint16_t)(avr->data[R_SPL] | avr->data[R_SPH] << 8); }

void stack_watch_attach(robot *r, const char *elf_path) {
    stack_watch *w = &r->stack_watch;
    memset(w, 0, sizeof *w);
    image_stacks s = stacks_of(elf_path);
    w->elf = elf_path;
    /* Unwatched: a .hex (no symbols). */
    if (s.end <= AVR_DATA_OFFSET || s.end - AVR_DATA_OFFSET > r->avr->ramend) return;
    w->stacks[0] = (watched_stack){(uint16_t)(s.end - AVR_DATA_OFFSET - 1u), (uint16_t)r->avr->ramend};
    w->n_stacks = 1;
    if (s.pool_size != 0 && s.pool + s.pool_size <= s.end - AVR_DATA_OFFSET) {
        w->pool = (uint16_t)s.pool;
        w->pool_end = (uint16_t)(s.pool + s.pool_size);
        w->block = s.block != 0 && s.block <= s.pool_size ? (uint16_t)s.block : 1u;
    }
    w->switch_lo = UINT32_MAX;
    for (size_t i = 0; i < N_SWITCH_CODE; i++) {
        if (s.code[i][1] == 0) continue;
        memcpy(w->switch_code[w->n_switch_code++], s.code[i], sizeof s.code[i]);
        if (s.code[i][0] < w->switch_lo) w->switch_lo = s.code[i][0];
        if (s.code[i][1] > w->switch_hi) w->switch_hi = s.code[i][1];
    }
    memcpy(w->thread_start, s.code[THREAD_START], sizeof w->thread_start);
    stack_watch_reset(r);
}

/* SP is on stack k from here: below its lowest yet is a new depth. */
static void move_to(stack_watch *w, int k) {
    w->on = k;
    w->mark = w->stacks[k].lowest;
}

void stack_watch_reset(robot *r) {
    stack_watch *w = &r->stack_watch;
    move_to(w, 0);
    w->switch_pc = 0;
}

unsigned stack_watch_main_used(const robot *r) {
    const stack_watch *w = &r->stack_watch;
    return w->n_stacks != 0 ? r->avr->ramend - w->stacks[0].lowest : 0;
}

uint32_t stack_watch_thread_deepest(const robot *r, uint32_t guard) {
    const stack_watch *w = &r->stack_watch;
    for (int k = 1; k < w->n_stacks; k++)
        if (w->stacks[k].floor == guard + STACK_GUARD_BYTES - 1u) return w->stacks[k].lowest + 1u;
    return 0;
}

/* The lowest SP of the thread stack holding sp: just above the guard at
 * the nearest block start below it (a stack may span several blocks); the
 * pool's start if no guard is found (the kernel built without
 * OS_CFG_STACK_CHECK). */
static uint16_t thread_floor(const stack_watch *w, const uint8_t *ram, uint16_t sp) {
    if (sp < w->pool + STACK_GUARD_BYTES - 1u) return w->pool - 1u;
    for (uint32_t k = (sp - (STACK_GUARD_BYTES - 1u) - w->pool) / w->block + 1u; k-- > 0;) {
        uint32_t at = w->pool + k * w->block;
        if (stack_guard_at(ram, at, w->pool_end)) return (uint16_t)(at + STACK_GUARD_BYTES - 1u);
    }
    return w->pool - 1u;
}

/* The thread stack with this floor, a new one if none has it (the least
 * recent one's place when all are taken). */
static int watched_thread_stack(stack_watch *w, uint16_t floor, uint16_t sp) {
    for (int k = 1; k < w->n_stacks; k++)
        if (w->stacks[k].floor == floor) return k;
    int k = w->n_stacks < MAX_WATCHED_STACKS ? w->n_stacks++ : 1;
    w->stacks[k] = (watched_stack){floor, sp};
    return k;
}

void stack_watch_found_stack(robot *r) {
    stack_watch *w = &r->stack_watch;
    uint16_t sp = stack_pointer(r->avr);
    int starting = w->switch_pc >= w->thread_start[0] && w->switch_pc < w->thread_start[1];
    w->switch_pc = 0;
    if (sp >= w->pool && sp < w->pool_end) {
        int k = watched_thread_stack(w, thread_floor(w, r->avr->data, sp), sp);
        if (starting) w->stacks[k].lowest = sp; /* a new thread: the last one's depth is not its */
        move_to(w, k);
    } else if (sp >= w->stacks[0].floor) {
        move_to(w, 0);
    } else {
        /* A stack of the firmware's own, in its variables (a context it
         * switches to with port_switch itself): its bounds are unknown, so
         * it is not judged until SP is back on a stack the kernel carved. */
        w->mark = 0;
    }
    if (sp < w->mark) stack_watch_below(r);
}

static uint16_t opcode_at(const avr_t *avr, uint32_t pc) {
    return pc + 1u <= avr->flashend ? (uint16_t)(avr->flash[pc] | avr->flash[pc + 1] << 8) : 0;
}

/* OUT io, Rr: 1011 1AAr rrrr AAAA. */
static int writes_io(uint16_t op, unsigned io) {
    return (op & 0xF800u) == 0xB800u && (((op >> 5) & 0x30u) | (op & 0x0Fu)) == io;
}

/* SPH is written and SPL is still to come (the next instruction, or the
 * one after SREG's): SP is half of a move, not yet where it goes. */
static int sp_half_written(const avr_t *avr) {
    uint16_t op = opcode_at(avr, avr->pc);
    return writes_io(op, SPL_IO) || (writes_io(op, SREG_IO) && writes_io(opcode_at(avr, avr->pc + 2u), SPL_IO));
}

/* SP is below the mark: a new depth of the stack it is on, and an
 * overflow if it is below the floor too. */
void stack_watch_below(robot *r) {
    stack_watch *w = &r->stack_watch;
    if (sp_half_written(r->avr)) return;
    uint16_t sp = stack_pointer(r->avr);
    watched_stack *on = &w->stacks[w->on];
    on->lowest = w->mark = sp;
    if (sp >= on->floor || w->overflowed) return;
    w->overflowed = w->on == 0 ? MAIN_STACK_OVERFLOWED : THREAD_STACK_OVERFLOWED;
    unsigned deep = (unsigned)(on->floor - sp);
    double t = (double)r->avr->cycle / r->avr->frequency;
    char place[400];
    code_place(w->elf, r->avr->pc, place, sizeof place); /* the function and line that went past */
    if (w->overflowed == MAIN_STACK_OVERFLOWED)
        fprintf(stderr, "openswarm-sim: %sthe main stack (main, interrupts, event handlers) overflowed at "
                        "%.6f s in %s: its stack pointer went %u byte%s into the RAM the image "
                        "reserves (up to 0x%04x), whose variables its frames now overlay; give it more room "
                        "by lowering the threads' \"stack\" in openswarm.json\n",
                r->console.prefix, t, place, deep, deep == 1 ? "" : "s", on->floor);
    else
        fprintf(stderr, "openswarm-sim: %sa thread's stack overflowed at %.6f s in %s: its stack "
                        "pointer went %u byte%s below its stack's lowest byte (0x%04x, above its guard), "
                        "and its frames now overlay the guard and what lies below; give the thread a larger \"stack\" "
                        "in openswarm.json (openswarm-sim --counters shows each stack's worst use)\n",
                r->console.prefix, t, place, deep, deep == 1 ? "" : "s", on->floor + 1u);
}
