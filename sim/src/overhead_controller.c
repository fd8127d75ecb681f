/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The overhead controller: system messages (RUN, SLEEP, ...) broadcast to
 * every robot over IR at given times (--ohc NAME@SECONDS). Each robot gets
 * the frame's flashes at exact cycles, through its analog comparator, in
 * the same wire format robots use (see ports/kilobot/src/devices/ir.c). */
#include <avr_acomp.h>
#include <sim_cycle_timers.h>
#include <sim_io.h>
#include <stdlib.h>
#include <string.h>

#include "sim.h"

#define BIT 269
#define HEADER_SLOTS 10
#define FRAME_BYTES 12
#define SLOTS (HEADER_SLOTS + FRAME_BYTES * 10)
#define FLASH_CYCLES 12
#define LIT_MV 1000

static const struct {
    const char *name;
    uint8_t type;
} system_messages[] = {
    {"reset", 0x83}, {"sleep", 0x84}, {"wakeup", 0x85}, {"charge", 0x86},
    {"voltage", 0x87}, {"run", 0x88},
};
#define N_SYSTEM_MESSAGES (sizeof system_messages / sizeof system_messages[0])

int ohc_parse(const char *text, ohc_message *m) {
    const char *at = strchr(text, '@');
    if (at != NULL) {
        for (unsigned i = 0; i < N_SYSTEM_MESSAGES; i++) {
            size_t n = strlen(system_messages[i].name);
            if ((size_t)(at - text) == n && strncmp(text, system_messages[i].name, n) == 0) {
                char *end;
                m->seconds = strtod(at + 1, &end);
                m->type = system_messages[i].type;
                if (*end == '\0' && m->seconds >= 0) return 0;
            }
        }
    }
    fprintf(stderr, "openswarm-sim: --ohc '%s': expected MESSAGE@SECONDS with MESSAGE one of "
                    "run, sleep, wakeup, reset, voltage, charge; e.g. --ohc sleep@1.5\n", text);
    return -1;
}

/* CRC-16 CCITT as avr-libc's _crc_ccitt_update computes it (seed 0xFFFF). */
static uint16_t crc_ccitt_update(uint16_t crc, uint8_t data) {
    data ^= (uint8_t)(crc & 0xFF);
    data ^= (uint8_t)(data << 4);
    return (uint16_t)(((uint16_t)data << 8 | (crc >> 8)) ^ (uint8_t)(data >> 4) ^ ((uint16_t)data << 3));
}

static int slot_lit(const uint8_t *frame, int slot) {
    if (slot < HEADER_SLOTS) return slot == 0 || slot == HEADER_SLOTS - 1;
    int s = slot - HEADER_SLOTS, bit = s % 10;
    return bit == 0 || bit == 9 || ((frame[s / 10] >> (bit - 1)) & 1);
}

/* One frame on its way to one robot: a timer steps through its edges. */
typedef struct broadcast {
    robot *to;
    uint8_t frame[FRAME_BYTES];
    int slot;   /* next slot to consider */
    int lit;    /* the LED is on now */
} broadcast;

static void set_ain0(robot *r, uint32_t mv) {
    avr_raise_irq(avr_io_getirq(r->avr, AVR_IOCTL_ACOMP_GETIRQ, ACOMP_IRQ_AIN0), mv);
}

static avr_cycle_count_t step(struct avr_t *avr, avr_cycle_count_t when, void *param) {
    (void)avr;
    broadcast *b = param;
    if (b->lit) { /* end of a flash: wait for the next lit slot */
        set_ain0(b->to, 0);
        b->lit = 0;
        int from = b->slot;
        while (b->slot < SLOTS && !slot_lit(b->frame, b->slot)) b->slot++;
        if (b->slot == SLOTS) return 0;
        return when + (avr_cycle_count_t)((b->slot - from) * BIT + BIT - FLASH_CYCLES);
    }
    set_ain0(b->to, LIT_MV);
    b->lit = 1;
    b->slot++;
    return when + FLASH_CYCLES;
}

static broadcast broadcasts[MAX_OHC_MESSAGES][MAX_ROBOTS];

void ohc_attach(robot *all, int n, const options *o) {
    for (int k = 0; k < o->n_ohc; k++) {
        uint8_t frame[FRAME_BYTES] = {0};
        frame[9] = o->ohc[k].type;
        uint16_t crc = 0xFFFF;
        for (int i = 0; i < 10; i++) crc = crc_ccitt_update(crc, frame[i]);
        frame[10] = (uint8_t)crc;
        frame[11] = (uint8_t)(crc >> 8);
        for (int i = 0; i < n; i++) {
            broadcast *b = &broadcasts[k][i];
            b->to = &all[i];
            memcpy(b->frame, frame, sizeof frame);
            b->slot = 0;
            b->lit = 0;
            avr_cycle_count_t at = (avr_cycle_count_t)(o->ohc[k].seconds * all[i].avr->frequency);
            avr_cycle_timer_register(all[i].avr, at + 1, step, b);
        }
    }
}
