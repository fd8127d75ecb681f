/* The proximity sensors' pre-processor. The receivers' output falls as the
 * light they get rises, so what an obstacle reflects is the reading with
 * the emitters off minus the reading at the end of their pulse (0 when the
 * pulse read higher: noise, no reflection). */
#include "openswarm/epuck.h"

uint8_t epuck_proximity_reflection(sys_device *dev, const void *in, uint8_t size, void *out,
                                   uint8_t capacity) {
    (void)dev;
    const epuck_proximity_samples *s = in;
    epuck_proximity_reading *r = out;
    if (size != sizeof *s || capacity < sizeof *r) return 0;
    for (unsigned i = 0; i < EPUCK_PROXIMITY_SENSORS; i++) {
        r->ambient[i] = s->off[i];
        r->reflected[i] = s->off[i] > s->pulsed[i] ? (uint16_t)(s->off[i] - s->pulsed[i]) : 0u;
    }
    return sizeof *r;
}
