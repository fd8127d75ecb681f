/* The IR distance pre-processor: a received frame's two gain readings
 * become the sender's distance in millimetres, through this robot's
 * calibration tables in EEPROM, by the classic Kilobot library's rules so
 * that its programs measure the same distances. */
#include "openswarm/kilobot.h"

#include <avr/eeprom.h>

/* Distance calibration: two tables of 14 big-endian readings in EEPROM,
 * low gain at 0x20 and high gain at 0x50; entry i is what the robot reads
 * from a sender 33 + 5 i mm away (readings fall with distance). */
#define TABLE_ENTRIES 14
#define LOW_GAIN_TABLE 0x20
#define HIGH_GAIN_TABLE 0x50
#define FIRST_MM 33u
#define STEP_MM 5u
/* The high gain saturates close by: it alone counts up to 700, the low
 * gain alone from 900, and in between a blend weighted by the high gain. */
#define HIGH_GAIN_ONLY_UP_TO 700
#define LOW_GAIN_ONLY_FROM 900
/* The classic's answer for a low-gain reading weaker than its whole table. */
#define LOW_GAIN_PAST_TABLE_MM 90u

static uint16_t table_entry(uint8_t table, uint8_t i) {
    const uint8_t *at = (const uint8_t *)(uintptr_t)(table + 2u * i); /* an EEPROM address */
    return (uint16_t)(eeprom_read_byte(at) << 8 | eeprom_read_byte(at + 1));
}

/* Millimetres beyond FIRST_MM (rounded down) for a reading no stronger
 * than entry i - 1 and stronger than entry i, on the straight line through
 * the two: past the last entry the line goes on. Readings compare as
 * unsigned, as the classic's do. */
static uint32_t along_segment(uint8_t table, uint8_t i, uint16_t reading) {
    uint16_t before = table_entry(table, (uint8_t)(i - 1u)), at = table_entry(table, i);
    if (before <= at) return STEP_MM * i; /* a flat end: no slope to follow */
    return STEP_MM * (i - 1u) + (uint32_t)(before - reading) * STEP_MM / (uint16_t)(before - at);
}

/* Millimetres beyond FIRST_MM for one gain's reading. A high-gain reading
 * weaker than the whole table is extrapolated from its last two entries; a
 * low-gain one counts as LOW_GAIN_PAST_TABLE_MM, as with the classic. */
static uint32_t beyond_first(uint8_t table, int16_t gain) {
    uint16_t reading = (uint16_t)gain;
    if (reading > table_entry(table, 0)) return 0;
    for (uint8_t i = 1; i < TABLE_ENTRIES; i++)
        if (reading > table_entry(table, i)) return along_segment(table, i, reading);
    if (table == LOW_GAIN_TABLE) return LOW_GAIN_PAST_TABLE_MM;
    return along_segment(table, TABLE_ENTRIES - 1u, reading);
}

uint8_t kilobot_ir_distance_mm(int16_t low_gain, int16_t high_gain) {
    uint32_t beyond;
    if (high_gain <= HIGH_GAIN_ONLY_UP_TO) {
        beyond = beyond_first(HIGH_GAIN_TABLE, high_gain);
    } else if (high_gain >= LOW_GAIN_ONLY_FROM) {
        beyond = beyond_first(LOW_GAIN_TABLE, low_gain);
    } else {
        uint32_t high = beyond_first(HIGH_GAIN_TABLE, high_gain);
        uint32_t low = beyond_first(LOW_GAIN_TABLE, low_gain);
        beyond = (high * (uint16_t)(LOW_GAIN_ONLY_FROM - high_gain) +
                  low * (uint16_t)(high_gain - HIGH_GAIN_ONLY_UP_TO)) /
                 (LOW_GAIN_ONLY_FROM - HIGH_GAIN_ONLY_UP_TO);
    }
    return beyond >= 255u - FIRST_MM ? 255u : (uint8_t)(FIRST_MM + beyond);
}

/* Rx: a frame whose CRC checks becomes a KILOBOT_EVENT_IR_RX, with the
 * sender's distance. */
uint8_t kilobot_ir_with_distance(sys_device *dev, const void *in, uint8_t size, void *out,
                                 uint8_t capacity) {
    uint8_t n = kilobot_ir_check_crc(dev, in, size, out, capacity);
    if (n != 0) {
        kilobot_ir_rx *rx = out;
        rx->distance_mm = kilobot_ir_distance_mm(rx->low_gain, rx->high_gain);
    }
    return n;
}
