/* The sensors' reusable pre-processor: a piecewise-linear table that turns
 * ADC counts into the user's unit (lux, mV, degrees). */
#include "openswarm/kilobot.h"

#include <string.h>

/* The value at raw on the segment a..b (a.raw < raw < b.raw), rounded to
 * the nearest. Magnitudes in 32 unsigned bits: the step from a is at most
 * 65535 counts times 65535 units, which a signed product could overflow. */
static int16_t between(const kilobot_table_point *a, const kilobot_table_point *b, int16_t raw) {
    uint16_t offset = (uint16_t)(raw - a->raw);
    uint16_t span = (uint16_t)(b->raw - a->raw);
    int32_t rise = (int32_t)b->value - a->value;
    uint32_t magnitude = (uint32_t)(rise < 0 ? -rise : rise);
    int32_t step = (int32_t)(((uint32_t)offset * magnitude + span / 2u) / span);
    return (int16_t)(a->value + (rise < 0 ? -step : step));
}

uint8_t kilobot_linear_table(sys_device *dev, const void *in, uint8_t size, void *out,
                             uint8_t capacity) {
    const kilobot_sensor_table *table = dev->params;
    if (table == NULL || table->count == 0u || size != sizeof(int16_t) ||
        capacity < sizeof(int16_t))
        return 0; /* not a reading, or no table installed */
    int16_t raw, value;
    memcpy(&raw, in, sizeof raw);
    const kilobot_table_point *p = table->points;
    uint8_t last = (uint8_t)(table->count - 1u);
    if (raw <= p[0].raw) {
        value = p[0].value; /* below the table: its first value */
    } else if (raw >= p[last].raw) {
        value = p[last].value; /* above: its last */
    } else {
        uint8_t i = 1;
        while (raw > p[i].raw) i++;
        value = between(&p[i - 1u], &p[i], raw);
    }
    memcpy(out, &value, sizeof value);
    return sizeof value;
}
