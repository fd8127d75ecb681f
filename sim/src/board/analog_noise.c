/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* Noise on a robot's analog inputs, as a real one's ADC readings carry:
 * each conversion reads the input's value plus gaussian noise, drawn from
 * the robot's own seeded sequence. The battery, light, temperature and IR
 * gain readings then jitter by about a count, so classic rand_hard() (the
 * temperature sensor's lowest bits) gives different numbers on different
 * robots, as it does on real ones, and a robot's distance estimates vary
 * by a millimetre or two.
 *
 * simavr converts the value an input holds when the conversion ends; it
 * announces each conversion's start (ADC_IRQ_OUT_TRIGGER, with the
 * channel): the noisy value is put on the channel then and the clean one
 * is remembered from every value the rest of the simulator raises. */
#include <avr_adc.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sim_io.h>

#include "sim.h"
#include "world/world_random.h"

#define CHANNELS (ADC_IRQ_TEMP + 1)
#define INTERNAL_REFERENCE_MV 1100 /* the temperature sensor's */

typedef struct analog_noise {
    avr_irq_t *input[CHANNELS]; /* looked up once: a conversion is a hot path */
    uint64_t rng;
    double sd_counts;
    uint32_t clean[CHANNELS]; /* each input's value without noise, millivolts */
    int adding;               /* our own raise: not a new clean value */
} analog_noise;

static void remember(struct avr_irq_t *irq, uint32_t value, void *param) {
    analog_noise *n = param;
    if (!n->adding) n->clean[irq->irq] = value;
}

static void converting(struct avr_irq_t *irq, uint32_t value, void *param) {
    (void)irq;
    analog_noise *n = param;
    avr_adc_mux_t mux;
    memset(&mux, 0, sizeof mux);
    memcpy(&mux, &value, sizeof value);
    int channel;
    double reference = KILOBOT_AVCC_MV;
    if (mux.kind == ADC_MUX_SINGLE && mux.src < ADC_IRQ_TEMP) {
        channel = (int)mux.src;
    } else if (mux.kind == ADC_MUX_TEMP) {
        channel = ADC_IRQ_TEMP;
        reference = INTERNAL_REFERENCE_MV;
    } else {
        return;
    }
    double mv = n->clean[channel] + n->sd_counts * reference / 1024.0 * world_random_normal(&n->rng);
    n->adding = 1;
    avr_raise_irq(n->input[channel], mv > 0 ? (uint32_t)lround(mv) : 0);
    n->adding = 0;
}

void analog_noise_attach(robot *r, uint64_t seed, double sd_counts) {
    analog_noise *n = calloc(1, sizeof *n);
    if (n == NULL) {
        fprintf(stderr, "openswarm-sim: out of memory for analog noise\n");
        exit(EXIT_CRASH);
    }
    n->rng = seed;
    n->sd_counts = sd_counts;
    for (int c = 0; c < CHANNELS; c++) {
        n->input[c] = avr_io_getirq(r->avr, AVR_IOCTL_ADC_GETIRQ, c);
        avr_irq_register_notify(n->input[c], remember, n);
    }
    avr_irq_register_notify(avr_io_getirq(r->avr, AVR_IOCTL_ADC_GETIRQ, ADC_IRQ_OUT_TRIGGER),
                            converting, n);
}
