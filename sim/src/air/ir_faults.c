/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* IR faults on a link (ir_faults.h).
 *
 * The wire format is on-off keying in slots (sim.h): a flipped slot is a
 * pulse lost (a 1 read as 0) or a pulse added in an empty slot (a 0 read
 * as 1). A lost pulse is drawn at its rising edge; added pulses are drawn
 * at the frame's start, one slot time apart from its start pulse, and sent
 * once the sender's clock has passed them by ADDED_MARGIN_CYCLES, so a
 * real pulse in the same slot is seen first (then nothing flips). A frame
 * cut short loses every pulse from a slot drawn at random to its end. A
 * pulse's fall always follows its rise: a receiver never sees the LED left
 * lit. */
#include <math.h>

#include "air/ir_faults.h"
#include "faults/faults.h"
#include "world/world_random.h"

#define FRAME_CYCLES ((avr_cycle_count_t)(IR_FRAME_SLOTS + 1) * IR_BIT_CYCLES)
/* Half a lockstep window: the added pulse lands at most this late. */
#define ADDED_MARGIN_CYCLES (IR_LATENCY_CYCLES / 2)
#define SAME_SLOT_CYCLES (IR_BIT_CYCLES / 4)

static double flip, cut; /* chances, 0..1 */
static uint64_t rng;

void ir_faults_configure(double flip_pct, double cut_pct, uint64_t seed) {
    flip = flip_pct / 100.0;
    cut = cut_pct / 100.0;
    rng = seed * 0x9E3779B97F4A7C15ull ^ 0x1F2E3D4C5B6A7988ull;
}

int ir_faults_active(void) { return flip > 0 || cut > 0; }

static double seconds_of(const robot *from, avr_cycle_count_t cycle) {
    return (double)cycle / (double)from->avr->frequency;
}

/* The slot a sender's cycle falls in, from the frame's start pulse. */
static int slot_of(const ir_link_faults *f, avr_cycle_count_t cycle) {
    return (int)((cycle - f->start + IR_BIT_CYCLES / 2) / IR_BIT_CYCLES);
}

/* Slots to the next flipped one: geometric, so a frame costs one draw per
 * flip rather than one per slot. */
static int slots_to_next_flip(void) {
    double u = world_random_uniform(&rng);
    double gap = floor(log(1.0 - u) / log(1.0 - flip)) + 1.0;
    return gap > IR_FRAME_SLOTS ? IR_FRAME_SLOTS : (int)gap;
}

void ir_faults_frame(ir_link_faults *f, const robot *from, int to, avr_cycle_count_t start) {
    f->start = start;
    f->cut_from = 0;
    f->n_added = f->next_added = 0;
    if (cut > 0 && world_random_uniform(&rng) < cut) {
        int slot = 1 + (int)(world_random_uniform(&rng) * (IR_FRAME_SLOTS - 1));
        f->cut_from = start + (avr_cycle_count_t)slot * IR_BIT_CYCLES - IR_BIT_CYCLES / 2;
        fault_log(FAULT_FRAME_CUT, seconds_of(from, start), to, "from=%d slot=%d", from->index, slot);
    }
    if (flip <= 0) return;
    for (int slot = slots_to_next_flip(); slot < IR_FRAME_SLOTS && f->n_added < IR_MAX_ADDED_PULSES;
         slot += slots_to_next_flip())
        f->added[f->n_added++] = start + (avr_cycle_count_t)slot * IR_BIT_CYCLES;
}

static int in_cut(const ir_link_faults *f, avr_cycle_count_t cycle) {
    return f->cut_from != 0 && cycle >= f->cut_from && cycle < f->start + FRAME_CYCLES;
}

int ir_faults_pass(ir_link_faults *f, const robot *from, int to, avr_cycle_count_t cycle, int lit) {
    if (!lit) return f->rise_passed;
    f->rise_passed = 0;
    if (in_cut(f, cycle)) return 0;
    if (flip > 0 && f->start != 0 && cycle < f->start + FRAME_CYCLES && world_random_uniform(&rng) < flip) {
        fault_log(FAULT_PULSE_LOST, seconds_of(from, cycle), to, "from=%d slot=%d", from->index,
                  slot_of(f, cycle));
        return 0;
    }
    f->rise_passed = 1;
    return 1;
}

static int on_a_real_pulse(avr_cycle_count_t at, const avr_cycle_count_t *rises, int n) {
    for (int i = n - 1; i >= 0; i--) {
        avr_cycle_count_t d = rises[i] > at ? rises[i] - at : at - rises[i];
        if (d <= SAME_SLOT_CYCLES) return 1;
        if (rises[i] + SAME_SLOT_CYCLES < at) return 0; /* rises are in order */
    }
    return 0;
}

avr_cycle_count_t ir_faults_added_due(ir_link_faults *f, const robot *from, int to,
                                      avr_cycle_count_t now, const avr_cycle_count_t *rises,
                                      int n_rises) {
    while (f->next_added < f->n_added) {
        avr_cycle_count_t at = f->added[f->next_added];
        if (at + ADDED_MARGIN_CYCLES > now || at + IR_ADDED_FLASH_CYCLES > now) return 0;
        f->next_added++;
        if (in_cut(f, at) || on_a_real_pulse(at, rises, n_rises)) continue;
        fault_log(FAULT_PULSE_ADDED, seconds_of(from, at), to, "from=%d slot=%d", from->index,
                  slot_of(f, at));
        return at;
    }
    return 0;
}
