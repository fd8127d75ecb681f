/* The IR distance pre-processor: a received frame's two gain readings
 * become the sender's distance in millimetres, through this robot's
 * calibration tables in EEPROM. */
#include "openswarm/kilobot.h"

#include <avr/eeprom.h>

/* Distance calibration: two tables of 14 big-endian readings in EEPROM,
 * low gain at 0x20 and high gain at 0x50; entry i is what the robot reads
 * from a sender 30 + 5 i mm away (readings fall with distance). */
#define TABLE_ENTRIES 14
#define LOW_GAIN_TABLE 0x20
#define HIGH_GAIN_TABLE 0x50
#define FIRST_MM 30
#define STEP_MM 5

static uint16_t table_entry(uint8_t table, uint8_t i) {
    const uint8_t *at = (const uint8_t *)(uint16_t)(table + 2u * i);
    return (uint16_t)(eeprom_read_byte(at) << 8 | eeprom_read_byte(at + 1));
}

/* Distance in mm, times 16, from one gain's reading: interpolated between
 * the two entries around it, clamped to the table's ends. */
static uint16_t distance_x16(uint8_t table, int16_t reading) {
    uint16_t r = reading < 0 ? 0 : (uint16_t)reading;
    if (r >= table_entry(table, 0)) return FIRST_MM * 16u;
    for (uint8_t i = 1; i < TABLE_ENTRIES; i++) {
        uint16_t hi = table_entry(table, (uint8_t)(i - 1u)), lo = table_entry(table, i);
        if (r >= lo) {
            uint16_t span = hi > lo ? (uint16_t)(hi - lo) : 1u;
            uint32_t frac = (uint32_t)(hi - r) * STEP_MM * 16u / span;
            return (uint16_t)((FIRST_MM + STEP_MM * (i - 1u)) * 16u + frac);
        }
    }
    return (FIRST_MM + STEP_MM * (TABLE_ENTRIES - 1u)) * 16u;
}

/* The high gain is precise far away but saturates close by: it is used
 * below 700, the low gain above 900, and a blend of both in between. */
uint8_t kilobot_ir_distance_mm(int16_t low_gain, int16_t high_gain) {
    uint16_t high = distance_x16(HIGH_GAIN_TABLE, high_gain);
    uint16_t low = distance_x16(LOW_GAIN_TABLE, low_gain);
    uint32_t x16;
    if (high_gain < 700)
        x16 = high;
    else if (high_gain > 900)
        x16 = low;
    else
        x16 = ((uint32_t)high * (uint32_t)(900 - high_gain) +
               (uint32_t)low * (uint32_t)(high_gain - 700)) / 200u;
    return (uint8_t)((x16 + 8u) / 16u);
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
