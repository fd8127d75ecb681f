/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* Cycle-exact measurement: marker writes and interrupt raises. */
#include <sim_interrupts.h>
#include <sim_io.h>
#include <sim_irq.h>

#include "sim.h"

static void mark_write(avr_t *avr, avr_io_addr_t addr, uint8_t v, void *param) {
    (void)param;
    if (avr->data[addr] != v) printf("mark %u %llu\n", (unsigned)v, (unsigned long long)avr->cycle);
    avr->data[addr] = v;
}

static void irq_raised(struct avr_irq_t *irq, uint32_t value, void *param) {
    (void)irq;
    const watched_irq *w = param;
    if (!value) return;
    if (w->robot < 0)
        printf("irq %d %llu\n", w->vector, (unsigned long long)w->avr->cycle);
    else
        printf("irq %d %llu robot %d\n", w->vector, (unsigned long long)w->avr->cycle, w->robot);
}

int measure_attach(robot *r, const options *o) {
    if (o->marks) avr_register_io_write(r->avr, GPIOR2_ADDR, mark_write, NULL);
    for (int i = 0; i < o->n_watched; i++) {
        r->watches[i].avr = r->avr;
        r->watches[i].vector = o->watched[i];
        r->watches[i].robot = o->robots > 1 ? r->index : -1;
        avr_irq_t *irq = avr_get_interrupt_irq(r->avr, (uint8_t)o->watched[i]);
        if (irq == NULL) {
            fprintf(stderr, "openswarm-sim: --watch-irq %d: %s has no such interrupt vector\n",
                    o->watched[i], r->avr->mmcu);
            return -1;
        }
        avr_irq_register_notify(irq, irq_raised, &r->watches[i]);
    }
    return 0;
}
