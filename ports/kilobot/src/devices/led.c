/* The RGB LED: each channel's two bits light one pin each. A pin lights
 * when it is an output driven low, so the colour lives in DDRC/DDRD with
 * PORT kept low: red PD5 (bit 0) and PD4 (bit 1), green PC3 and PC2, blue
 * PC5 and PC4. */
#include "openswarm/kilobot.h"

#include <avr/io.h>

#define RED_MASK (_BV(PD5) | _BV(PD4))
#define GREEN_BLUE_MASK (_BV(PC2) | _BV(PC3) | _BV(PC4) | _BV(PC5))

void kilobot_led_apply(uint8_t rgb) {
    uint8_t r = rgb & 3u, g = (rgb >> 2) & 3u, b = (rgb >> 4) & 3u;
    uint8_t d = (uint8_t)(((r & 1u) ? _BV(PD5) : 0) | ((r & 2u) ? _BV(PD4) : 0));
    uint8_t c = (uint8_t)(((g & 1u) ? _BV(PC3) : 0) | ((g & 2u) ? _BV(PC2) : 0) |
                          ((b & 1u) ? _BV(PC5) : 0) | ((b & 2u) ? _BV(PC4) : 0));
    PORTD &= (uint8_t)~RED_MASK;
    PORTC &= (uint8_t)~GREEN_BLUE_MASK;
    DDRD = (uint8_t)((DDRD & (uint8_t)~RED_MASK) | d);
    DDRC = (uint8_t)((DDRC & (uint8_t)~GREEN_BLUE_MASK) | c);
}

static void led_write(sys_device *dev, const void *raw, uint8_t size) {
    (void)dev;
    if (size >= 1) kilobot_led_apply(*(const uint8_t *)raw);
}

sys_device kilobot_led = {"led", SYS_DEVICE_OUTPUT, KILOBOT_EVENT_LED, 0, NULL, NULL, led_write, NULL, 0};
