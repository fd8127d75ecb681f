/* The 16-position selector: the board reads it as often as it likes; an
 * event comes when the position changes (and once, the first reading). */
#include "devices_internal.h"

static uint8_t last = 0xFF; /* none yet */

void epuck_selector_forget(void) { last = 0xFF; }

uint8_t epuck_selector_changes(sys_device *dev, const void *in, uint8_t size, void *out,
                               uint8_t capacity) {
    (void)dev;
    if (size != 1 || capacity < 1) return 0;
    uint8_t position = (uint8_t)(*(const uint8_t *)in & 0x0Fu);
    if (position == last) return 0;
    last = position;
    *(uint8_t *)out = position;
    return 1;
}
