/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* ADC auto-trigger from the analog comparator, which simavr 1.6 lacks.
 *
 * With ADATE set and ADTS = 001 the ATmega328P starts a conversion when
 * the comparator's interrupt flag (ACI) rises, whether or not its interrupt
 * is enabled. The classic Kilobot library measures a sender's distance that
 * way: the frame's start pulse starts the high-gain conversion, its stop
 * pulse the low-gain one. simavr 1.6 accepts the setting but never starts
 * the conversion (it implements free running only), so its receivers read
 * whatever the ADC last held.
 *
 * Here every change of the comparator's output that sets ACI, by the edge
 * ACSR's ACIS bits select, raises the ADC's trigger input when ADCSRB
 * selects the comparator; simavr's ADC itself checks ADATE and ignores a
 * trigger during a conversion, as the chip does. The chip starts one only
 * on a rising ACI, so an edge while the flag is still set starts none; the
 * model starts one at each such edge, as if the firmware cleared the flag
 * (its interrupt does) before the next. */
#include <avr_acomp.h>
#include <avr_adc.h>
#include <sim_io.h>

#include "sim.h"

/* The ATmega328P's registers (data addresses) and bits. */
#define ACSR_ADDR 0x50
#define ADCSRB_ADDR 0x7B
#define ACIS_MASK 0x03 /* ACIS1:0: 00 toggle, 10 falling, 11 rising */
#define ADTS_MASK 0x07
#define ADTS_COMPARATOR 0x01

/* Does this change of the comparator output set ACI? */
static int sets_flag(uint8_t acis, uint32_t output) {
    switch (acis) {
    case 0x00: return 1;
    case 0x02: return output == 0;
    case 0x03: return output != 0;
    default: return 0; /* 01 is reserved */
    }
}

static void comparator_changed(struct avr_irq_t *irq, uint32_t output, void *param) {
    (void)irq;
    avr_t *avr = param;
    if ((avr->data[ADCSRB_ADDR] & ADTS_MASK) != ADTS_COMPARATOR) return;
    if (!sets_flag(avr->data[ACSR_ADDR] & ACIS_MASK, output)) return;
    avr_raise_irq(avr_io_getirq(avr, AVR_IOCTL_ADC_GETIRQ, ADC_IRQ_IN_TRIGGER), 1);
}

void adc_trigger_attach(avr_t *avr) {
    avr_irq_register_notify(avr_io_getirq(avr, AVR_IOCTL_ACOMP_GETIRQ, ACOMP_IRQ_OUT),
                            comparator_changed, avr);
}
