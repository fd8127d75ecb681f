/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* --ir-log: the frames on the air, decoded from each sender's flashes by
 * the Kilobot wire format alone - not by the firmware's receiver - so what
 * a robot sends is checked against the format classic robots and the
 * overhead controller use.
 *
 * Slots (sim.h's IR_* format) count from the start pulse. The frame is
 * reported at its last stop bit, or as broken when it stops short or a
 * pulse falls outside the format: the bytes (9 data, the type), whether the
 * CRC matches the last two, how far the worst pulse lay from its slot, and
 * who is in range. */
#include <stdlib.h>
#include <string.h>

#include "sim.h"

#define OFF_CYCLES (IR_BIT_CYCLES / 4) /* a pulse this far from its slot is off the format */

typedef struct air_frame {
    avr_cycle_count_t start; /* the start pulse's cycle; 0: no frame under way */
    int last_slot;
    uint8_t bytes[IR_FRAME_BYTES];
    int worst;          /* cycles between a pulse and its slot, at most */
    const char *broken; /* what was wrong, NULL: nothing yet */
} air_frame;

static air_frame frames[MAX_ROBOTS];
static int enabled;

void ir_log_enable(void) { enabled = 1; }

static void report(const robot *from, const air_frame *f, const char *in_range) {
    double s = (double)f->start / (double)from->avr->frequency;
    printf("%s[%10.6f s] ir     ", from->console.prefix, s);
    for (int i = 0; i < 9; i++) printf("%02x ", f->bytes[i]);
    uint16_t crc = (uint16_t)(f->bytes[IR_CRC_BYTES] | f->bytes[IR_CRC_BYTES + 1] << 8);
    if (f->broken != NULL)
        printf("type %02x BROKEN (%s, after slot %d)", f->bytes[9], f->broken, f->last_slot);
    else
        printf("type %02x crc %s, pulses within %d cycles of their slots", f->bytes[9],
               crc == ir_frame_crc(f->bytes) ? "ok" : "BAD", f->worst);
    printf(", in range of %s\n", in_range[0] ? in_range : "nobody");
    fflush(stdout);
}

/* Is a pulse in this slot allowed, and where do its data go? */
static const char *place_pulse(air_frame *f, int slot) {
    if (slot <= f->last_slot) return "two pulses in one slot";
    if (slot < IR_HEADER_SLOTS) return slot == IR_HEADER_SLOTS - 1 ? NULL : "a pulse inside the header";
    int data = slot - IR_HEADER_SLOTS, bit = data % 10;
    for (int s = f->last_slot + 1; s < slot; s++) /* the start and stop bits skipped are missing */
        if (s >= IR_HEADER_SLOTS && ((s - IR_HEADER_SLOTS) % 10 == 0 || (s - IR_HEADER_SLOTS) % 10 == 9))
            return "a start or stop bit missing";
    if (bit >= 1 && bit <= 8) f->bytes[data / 10] |= (uint8_t)(1u << (bit - 1));
    return NULL;
}

/* A rising flash of robot from's IR LED. A broken frame is reported once
 * its time is over, so its remaining pulses do not look like new frames. */
void ir_log_flash(const robot *from, avr_cycle_count_t cycle, const char *in_range) {
    if (!enabled) return;
    air_frame *f = &frames[from->index];
    if (f->start != 0 && cycle >= f->start + (avr_cycle_count_t)(IR_FRAME_SLOTS + 1) * IR_BIT_CYCLES) {
        if (f->broken == NULL) f->broken = "stopped short";
        report(from, f, in_range);
        f->start = 0;
    }
    if (f->start == 0) {
        memset(f, 0, sizeof *f);
        f->start = cycle;
        return;
    }
    /* Slots count from the start pulse, to the nearest: each pulse is a few
     * cycles after its slot begins, the start pulse too. */
    avr_cycle_count_t since = cycle - f->start;
    int slot = (int)((since + IR_BIT_CYCLES / 2) / IR_BIT_CYCLES);
    int off = abs((int)(since - (avr_cycle_count_t)slot * IR_BIT_CYCLES));
    if (off > f->worst) f->worst = off;
    const char *wrong = off > OFF_CYCLES ? "a pulse between slots" : place_pulse(f, slot);
    if (wrong != NULL && f->broken == NULL) f->broken = wrong;
    if (f->broken == NULL) f->last_slot = slot;
    if (slot == IR_FRAME_SLOTS - 1 && f->broken == NULL) {
        report(from, f, in_range);
        f->start = 0;
    }
}
