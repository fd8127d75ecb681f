/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The overhead controller: system messages (RUN, SLEEP, CALIB, ...)
 * broadcast to every robot over IR at given times (--ohc NAME[:VALUES]@SECONDS).
 * Each robot gets the frame's flashes at exact cycles, through its analog
 * comparator, in the same wire format robots use (ports/kilobot/src/devices/ir.c). */
#include <avr_acomp.h>
#include <sim_cycle_timers.h>
#include <sim_io.h>
#include <stdlib.h>
#include <string.h>

#include "sim.h"

#define FLASH_CYCLES 12

#define CALIB 0x8A
#define NO_MODE (-1)

/* The messages --ohc knows. A CALIB message's data holds the mode, the uid
 * (little-endian) at 1, the duties to turn left at 3, right at 4 and go
 * straight at 5 and 6 (KiloGUI's layout); READUID's the uid bit at 0. */
typedef struct message_kind {
    const char *name;
    uint8_t type;
    int mode;         /* data[0] of a CALIB message, NO_MODE otherwise */
    int at, values;   /* data index of the first value, how many values */
    long max;         /* each value 0..max; a value above 255 takes two bytes */
    const char *form; /* what the values look like */
    const char *example;
} message_kind;

static const message_kind kinds[] = {
    {"run", 0x88, NO_MODE, 0, 0, 0, "", "run@1.5"},
    {"sleep", 0x84, NO_MODE, 0, 0, 0, "", "sleep@1.5"},
    {"wakeup", 0x85, NO_MODE, 0, 0, 0, "", "wakeup@1.5"},
    {"pause", 0x85, NO_MODE, 0, 0, 0, "", "pause@1.5"}, /* KiloGUI names WAKEUP Pause */
    {"reset", 0x83, NO_MODE, 0, 0, 0, "", "reset@1.5"},
    {"voltage", 0x87, NO_MODE, 0, 0, 0, "", "voltage@1.5"},
    {"charge", 0x86, NO_MODE, 0, 0, 0, "", "charge@1.5"},
    {"boot", 0x80, NO_MODE, 0, 0, 0, "", "boot@1.5"},
    {"calib-save", CALIB, 0, 0, 0, 0, "", "calib-save@3"},
    {"calib-uid", CALIB, 1, 1, 1, 65535, "UID", "calib-uid:42@1"},
    {"calib-left", CALIB, 2, 3, 1, 255, "DUTY", "calib-left:70@1"},
    {"calib-right", CALIB, 3, 4, 1, 255, "DUTY", "calib-right:70@1"},
    {"calib-straight", CALIB, 4, 5, 2, 255, "LEFT,RIGHT", "calib-straight:65,68@1"},
    {"readuid", 0x89, NO_MODE, 0, 1, 15, "BIT", "readuid:0@1"},
};
#define N_KINDS (sizeof kinds / sizeof kinds[0])

static const message_kind *kind_named(const char *name, size_t length) {
    for (unsigned i = 0; i < N_KINDS; i++)
        if (strlen(kinds[i].name) == length && strncmp(name, kinds[i].name, length) == 0)
            return &kinds[i];
    return NULL;
}

static void unknown_message(const char *text) {
    fprintf(stderr, "openswarm-sim: --ohc '%s': expected MESSAGE@SECONDS with MESSAGE one of",
            text);
    for (unsigned i = 0; i < N_KINDS; i++)
        fprintf(stderr, "%s %s%s%s", i == 0 ? "" : ",", kinds[i].name, *kinds[i].form ? ":" : "",
                kinds[i].form);
    fprintf(stderr, "; e.g. --ohc sleep@1.5\n");
}

/* ":V1,V2...", exactly k->values of them, from p up to end, into data. */
static int parse_values(const message_kind *k, const char *p, const char *end, uint8_t *data) {
    if (k->values == 0) return p == end ? 0 : -1;
    for (int i = 0; i < k->values; i++) {
        if (*p != (i == 0 ? ':' : ',')) return -1;
        char *stop;
        long v = strtol(++p, &stop, 10);
        if (stop == p || v < 0 || v > k->max) return -1;
        data[k->at + i] = (uint8_t)v;
        if (k->max > 255) data[k->at + i + 1] = (uint8_t)(v >> 8);
        p = stop;
    }
    return p == end ? 0 : -1;
}

static void kind_usage(const char *text, const message_kind *k) {
    if (k->values == 0)
        fprintf(stderr,
                "openswarm-sim: --ohc '%s': expected %s@SECONDS (it takes no values), "
                "e.g. --ohc %s\n",
                text, k->name, k->example);
    else
        fprintf(stderr,
                "openswarm-sim: --ohc '%s': expected %s:%s@SECONDS, values 0..%ld, "
                "e.g. --ohc %s\n",
                text, k->name, k->form, k->max, k->example);
}

int ohc_parse(const char *text, ohc_message *m) {
    const char *at = strrchr(text, '@');
    size_t length = strcspn(text, ":@");
    const message_kind *k = kind_named(text, length);
    if (k == NULL) {
        unknown_message(text);
        return -1;
    }
    memset(m, 0, sizeof *m);
    m->type = k->type;
    if (k->mode != NO_MODE) m->data[0] = (uint8_t)k->mode;
    if (at == NULL || parse_values(k, text + length, at, m->data) != 0) {
        kind_usage(text, k);
        return -1;
    }
    char *end;
    m->seconds = strtod(at + 1, &end);
    if (end == at + 1 || *end != '\0' || !(m->seconds >= 0 && m->seconds < 1e9)) { /* NaN too */
        fprintf(stderr, "openswarm-sim: --ohc '%s': expected seconds after '@', e.g. --ohc %s\n",
                text, k->example);
        return -1;
    }
    return 0;
}

static int slot_lit(const uint8_t *frame, int slot) {
    if (slot < IR_HEADER_SLOTS) return slot == 0 || slot == IR_HEADER_SLOTS - 1;
    int s = slot - IR_HEADER_SLOTS, bit = s % 10;
    return bit == 0 || bit == 9 || ((frame[s / 10] >> (bit - 1)) & 1);
}

/* One frame on its way to one robot: a timer steps through its edges. */
typedef struct broadcast {
    robot *to;
    uint8_t frame[IR_FRAME_BYTES];
    int slot; /* next slot to consider */
    int lit;  /* the LED is on now */
    avr_cycle_count_t next; /* the robot's cycle of its next step; 0: sent */
} broadcast;

static broadcast *broadcasts[MAX_OHC_MESSAGES]; /* one per robot */

static void set_ain0(robot *r, uint32_t mv) {
    avr_raise_irq(avr_io_getirq(r->avr, AVR_IOCTL_ACOMP_GETIRQ, ACOMP_IRQ_AIN0), mv);
}

static avr_cycle_count_t next_step(broadcast *b, avr_cycle_count_t when) {
    if (b->lit) { /* end of a flash: wait for the next lit slot */
        set_ain0(b->to, 0);
        b->lit = 0;
        int from = b->slot;
        while (b->slot < IR_FRAME_SLOTS && !slot_lit(b->frame, b->slot)) b->slot++;
        if (b->slot == IR_FRAME_SLOTS) return 0;
        return when + (avr_cycle_count_t)((b->slot - from) * IR_BIT_CYCLES + IR_BIT_CYCLES - FLASH_CYCLES);
    }
    set_ain0(b->to, IR_LIT_MV);
    b->lit = 1;
    b->slot++;
    return when + FLASH_CYCLES;
}

static avr_cycle_count_t step(struct avr_t *avr, avr_cycle_count_t when, void *param) {
    (void)avr;
    broadcast *b = param;
    b->next = next_step(b, when);
    return b->next;
}

static int n_broadcasts;

/* A reset cancels the robot's timers (simavr's avr_reset): the messages
 * still to come, or under way, go on from where they were. */
void ohc_robot_reset(robot *r) {
    for (int k = 0; k < n_broadcasts; k++) {
        broadcast *b = &broadcasts[k][r->index];
        if (b->next == 0) continue;
        avr_cycle_count_t in = b->next > r->avr->cycle ? b->next - r->avr->cycle : 1;
        avr_cycle_timer_register(r->avr, in, step, b);
    }
}

void ohc_frame(const ohc_message *m, uint8_t frame[IR_FRAME_BYTES]) {
    memset(frame, 0, IR_FRAME_BYTES);
    memcpy(frame, m->data, sizeof m->data);
    frame[9] = m->type;
    uint16_t crc = ir_frame_crc(frame);
    frame[IR_CRC_BYTES] = (uint8_t)crc;
    frame[IR_CRC_BYTES + 1] = (uint8_t)(crc >> 8);
}

void ohc_attach(robot *all, int n, const options *o) {
    n_broadcasts = o->n_ohc;
    for (int k = 0; k < o->n_ohc; k++) {
        broadcasts[k] = calloc((size_t)n, sizeof(broadcast));
        if (broadcasts[k] == NULL) {
            fprintf(stderr, "openswarm-sim: out of memory for --ohc on %d robots\n", n);
            exit(EXIT_CRASH);
        }
        uint8_t frame[IR_FRAME_BYTES];
        ohc_frame(&o->ohc[k], frame);
        for (int i = 0; i < n; i++) {
            broadcast *b = &broadcasts[k][i];
            b->to = &all[i];
            memcpy(b->frame, frame, sizeof frame);
            b->slot = 0;
            b->lit = 0;
            avr_cycle_count_t at = (avr_cycle_count_t)(o->ohc[k].seconds * all[i].avr->frequency);
            b->next = at + 1;
            avr_cycle_timer_register(all[i].avr, at + 1, step, b);
        }
    }
}
