/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* What a Kilobot's EEPROM and analog inputs hold, set before it runs. */
#include <avr_adc.h>
#include <avr_eeprom.h>
#include <avr_extint.h>
#include <avr_ioport.h>
#include <sim_io.h>
#include <string.h>

#include "sim.h"

static const uint16_t calibration_address[4] = {0x05, 0x09, 0x0C, 0x14};
#define OSCCAL_ADDRESS 0x01
#define UID_ADDRESS 0xB0
/* Distance tables: 14 big-endian readings, entry i for 33 + 5 i mm, as
 * kilolib (classic and ours) reads them. */
#define LOW_GAIN_TABLE 0x20
#define HIGH_GAIN_TABLE 0x50
#define TABLE_ENTRIES 14

static void write_eeprom(avr_t *avr, uint16_t address, const uint8_t *bytes, uint32_t n) {
    avr_eeprom_desc_t d = {(uint8_t *)bytes, address, n};
    avr_ioctl(avr, AVR_IOCTL_EEPROM_SET, &d);
}

void board_eeprom_write(void *avr, uint16_t address, const uint8_t *bytes, uint32_t n) {
    write_eeprom(avr, address, bytes, n);
}

static void set_analog(avr_t *avr, int channel, int millivolts) {
    if (millivolts >= 0)
        avr_raise_irq(avr_io_getirq(avr, AVR_IOCTL_ADC_GETIRQ, channel), (uint32_t)millivolts);
}

void board_configure(avr_t *avr, const options *o, int uid, const int calibration[4]) {
    avr->vcc = avr->avcc = avr->aref = KILOBOT_AVCC_MV;
    /* simavr 1.6 polls INT0/INT1 pins held low every cycle, enabled or not,
     * to repeat a level-triggered interrupt; PD3 (INT1) is the right motor's
     * PWM output, so a robot whose right motor ran cost three times as much
     * to simulate. A Kilobot uses neither interrupt: one trigger per fall. */
    avr_extint_set_strict_lvl_trig(avr, 0, 0);
    avr_extint_set_strict_lvl_trig(avr, 1, 0);
    set_analog(avr, ADC_IRQ_ADC7, o->light_mv);
    set_analog(avr, ADC_IRQ_ADC6, o->voltage_mv);
    set_analog(avr, ADC_IRQ_TEMP, o->temperature_mv);
    /* The charger's status output holds PD0 high, low while it charges. */
    avr_raise_irq(avr_io_getirq(avr, AVR_IOCTL_IOPORT_GETIRQ('D'), IOPORT_IRQ_PIN0), !o->charging);
    kilobot_eeprom_fill(board_eeprom_write, avr, uid, calibration);
}

void kilobot_eeprom_fill(eeprom_write_fn write, void *ctx, int uid, const int calibration[4]) {
    for (int i = 0; i < 4; i++) {
        if (calibration[i] < 0) continue;
        uint8_t v = (uint8_t)calibration[i];
        write(ctx, calibration_address[i], &v, 1);
    }
    uint8_t low[2 * TABLE_ENTRIES], high[2 * TABLE_ENTRIES];
    for (int i = 0; i < TABLE_ENTRIES; i++) {
        int mm = 33 + 5 * i, l = ir_low_gain_reading(mm), h = ir_high_gain_reading(mm);
        low[2 * i] = (uint8_t)(l >> 8);
        low[2 * i + 1] = (uint8_t)l;
        high[2 * i] = (uint8_t)(h >> 8);
        high[2 * i + 1] = (uint8_t)h;
    }
    write(ctx, LOW_GAIN_TABLE, low, sizeof low);
    write(ctx, HIGH_GAIN_TABLE, high, sizeof high);
    if (uid >= 0) {
        uint8_t bytes[2] = {(uint8_t)(uid & 0xFF), (uint8_t)(uid >> 8)}; /* little-endian */
        write(ctx, UID_ADDRESS, bytes, 2);
    }
}

void board_pins_again(avr_t *avr) {
    /* Raised both ways: simavr may skip a raise to the value a pin holds. */
    avr_irq_t *charger = avr_io_getirq(avr, AVR_IOCTL_IOPORT_GETIRQ('D'), IOPORT_IRQ_PIN0);
    uint32_t level = charger->value;
    avr_raise_irq(charger, !level);
    avr_raise_irq(charger, level);
}

void kilobot_eeprom_erase_calibration(eeprom_write_fn write, void *ctx) {
    uint8_t blank[2 * TABLE_ENTRIES];
    memset(blank, 0xFF, sizeof blank);
    write(ctx, OSCCAL_ADDRESS, blank, 1);
    for (int i = 0; i < 4; i++) write(ctx, calibration_address[i], blank, 1);
    write(ctx, LOW_GAIN_TABLE, blank, sizeof blank);
    write(ctx, HIGH_GAIN_TABLE, blank, sizeof blank);
}
