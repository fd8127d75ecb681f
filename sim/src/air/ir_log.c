/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* --ir-log: the frames on the air, decoded from each sender's flashes by
 * the Kilobot wire format alone - not by the firmware's receiver - so what
 * a robot sends is checked against the format classic robots and the
 * overhead controller use.
 *
 * Slots (sim.h's IR_* format) are timed the way receivers time them: the
 * header's from its start pulse, each byte's from its own start bit, which
 * must come one slot after the stop before it. Senders' bits are not all
 * IR_BIT_CYCLES long (the classic library's are a cycle longer, with a few
 * cycles between bytes); counted from the start pulse alone they drift more
 * than half a slot by the frame's end, counted from each start bit they
 * drift by a byte's worth at most, as in a receiver.
 *
 * The frame is reported at its last stop bit, or as broken when it stops
 * short or a pulse falls outside the format: the bytes (9 data, the type),
 * whether the CRC matches the last two, how far the worst pulse lay from its
 * slot, and who is in range. */
#include <stdlib.h>
#include <string.h>

#include "sim.h"

#define OFF_CYCLES (IR_BIT_CYCLES / 4) /* a pulse this far from its slot is off the format */
#define HEADER (-1)                    /* the byte index while the header is under way */
#define STOP_SLOT 9                    /* of a byte's or the header's, from its first pulse */
/* Within a frame pulses are at most STOP_SLOT slots apart: a longer silence ends it. */
#define SILENCE_CYCLES ((avr_cycle_count_t)(STOP_SLOT + 1) * IR_BIT_CYCLES)

typedef struct air_frame {
    avr_cycle_count_t start;  /* the start pulse's cycle; 0: no frame under way */
    avr_cycle_count_t origin; /* the header's start pulse or the current byte's start bit */
    avr_cycle_count_t last;   /* the last pulse's cycle */
    int byte;                 /* HEADER, or the byte under way */
    int slot;                 /* the last pulse's slot, from origin; STOP_SLOT: a unit is complete */
    uint8_t bytes[IR_FRAME_BYTES];
    int worst;          /* cycles between a pulse and its slot, at most */
    const char *broken; /* what was wrong, NULL: nothing yet */
} air_frame;

static air_frame *frames; /* one per robot */
static int enabled;

int ir_log_enabled(void) { return enabled; }

void ir_log_enable(int robots) {
    frames = calloc((size_t)robots, sizeof *frames);
    if (frames == NULL) {
        fprintf(stderr, "openswarm-sim: out of memory for --ir-log's %d robots\n", robots);
        exit(EXIT_CRASH);
    }
    enabled = 1;
}

/* The format's slot of the last pulse, from the start pulse: where a
 * broken frame stopped making sense. */
static int frame_slot(const air_frame *f) {
    return f->byte == HEADER ? f->slot : IR_HEADER_SLOTS + 10 * f->byte + f->slot;
}

static void report(const robot *from, const air_frame *f, const char *in_range) {
    double s = (double)f->start / (double)from->avr->frequency;
    printf("%s[%10.6f s] ir     ", from->console.prefix, s);
    for (int i = 0; i < 9; i++) printf("%02x ", f->bytes[i]);
    uint16_t crc = (uint16_t)(f->bytes[IR_CRC_BYTES] | f->bytes[IR_CRC_BYTES + 1] << 8);
    if (f->broken != NULL)
        printf("type %02x BROKEN (%s, after slot %d)", f->bytes[9], f->broken, frame_slot(f));
    else
        printf("type %02x crc %s, pulses within %d cycles of their slots", f->bytes[9],
               crc == ir_frame_crc(f->bytes) ? "ok" : "BAD", f->worst);
    printf(", in range of %s\n", in_range[0] ? in_range : "nobody");
    stdout_flush();
}

/* The slot nearest to a pulse `since` cycles after the pulse slots count
 * from; its distance from that slot is kept if it is the frame's worst. */
static int nearest_slot(air_frame *f, avr_cycle_count_t since, int *off) {
    int slot = (int)((since + IR_BIT_CYCLES / 2) / IR_BIT_CYCLES);
    *off = abs((int)(since - (avr_cycle_count_t)slot * IR_BIT_CYCLES));
    if (*off > f->worst) f->worst = *off;
    return slot;
}

/* A pulse after a complete header or byte: the next byte's start bit, one
 * slot after that stop, starts the byte's own slots. */
static const char *place_start_bit(air_frame *f, avr_cycle_count_t cycle) {
    int off, slot = nearest_slot(f, cycle - f->last, &off);
    if (off > OFF_CYCLES) return "a pulse between slots";
    if (slot != 1) return "a start bit out of its slot";
    f->byte++;
    f->origin = cycle;
    f->slot = 0;
    return NULL;
}

/* A pulse inside the header or a byte: a data bit or the stop. */
static const char *place_pulse(air_frame *f, avr_cycle_count_t cycle) {
    int off, slot = nearest_slot(f, cycle - f->origin, &off);
    if (off > OFF_CYCLES) return "a pulse between slots";
    if (slot <= f->slot) return "two pulses in one slot";
    if (slot > STOP_SLOT) return "a stop bit missing";
    if (f->byte == HEADER && slot != STOP_SLOT) return "a pulse inside the header";
    if (slot != STOP_SLOT) f->bytes[f->byte] |= (uint8_t)(1u << (slot - 1));
    f->slot = slot;
    return NULL;
}

static void begin(air_frame *f, avr_cycle_count_t cycle) {
    memset(f, 0, sizeof *f);
    f->start = f->origin = f->last = cycle;
    f->byte = HEADER;
}

/* A rising flash of robot from's IR LED. A broken frame is reported once
 * its pulses stop, so the rest of them do not look like new frames. */
void ir_log_flash(const robot *from, avr_cycle_count_t cycle, const char *in_range) {
    if (!enabled) return;
    air_frame *f = &frames[from->index];
    if (f->start != 0 && cycle - f->last > SILENCE_CYCLES) {
        if (f->broken == NULL) f->broken = "stopped short";
        report(from, f, in_range);
        f->start = 0;
    }
    if (f->start == 0) {
        begin(f, cycle);
        return;
    }
    if (f->broken == NULL) {
        int unit_complete = f->slot == STOP_SLOT;
        f->broken = unit_complete ? place_start_bit(f, cycle) : place_pulse(f, cycle);
    }
    f->last = cycle;
    if (f->broken == NULL && f->byte == IR_FRAME_BYTES - 1 && f->slot == STOP_SLOT) {
        report(from, f, in_range);
        f->start = 0;
    }
}
