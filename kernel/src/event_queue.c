/* The queue of sent, not yet dispatched event occurrences: one byte ring
 * holding [event id][size][data...] records, so an occurrence costs two
 * bytes plus its data and no fixed-size slot is wasted. Sends push with
 * interrupts masked; only the system thread pops. */
#include "kernel_internal.h"

#define QUEUE_BYTES ((uint8_t)OS_CFG_EVENT_QUEUE_BYTES)
#define HEADER_BYTES 2u

static uint8_t ring[OS_CFG_EVENT_QUEUE_BYTES];
static uint8_t head; /* next byte to pop; os.queued_bytes follow it */

void os_event_queue_reset(void) { head = os.queued_bytes = 0; }

/* The ring index after i. */
static inline uint8_t after(uint8_t i) { return (uint8_t)(i + 1u == QUEUE_BYTES ? 0u : i + 1u); }

static inline uint8_t wrap(uint16_t index) {
    return (uint8_t)(index >= QUEUE_BYTES ? index - QUEUE_BYTES : index);
}

/* Byte by byte with the wrap test inline: occurrences are a few bytes, so
 * this beats splitting the copy in two memcpy calls. */
bool os_event_queue_push(sys_event_id event, const void *data, uint8_t size) {
    uint8_t used = os.queued_bytes;
    if ((uint16_t)used + HEADER_BYTES + size > QUEUE_BYTES) return false;
    uint8_t at = wrap((uint16_t)head + used);
    ring[at] = event;
    at = after(at);
    ring[at] = size;
    const uint8_t *src = (const uint8_t *)data;
    for (uint8_t n = size; n != 0; n--) {
        at = after(at);
        ring[at] = *src++;
    }
    used = (uint8_t)(used + HEADER_BYTES + size);
    os.queued_bytes = used;
    if (used > os.stats.event_queue_peak) os.stats.event_queue_peak = used;
    return true;
}

bool os_event_queue_pop(sys_event_data *out) {
    uint8_t at = head;
    sys_event_id event = ring[at];
    at = after(at);
    uint8_t size = ring[at];
    at = after(at);
    os.queued_bytes = (uint8_t)(os.queued_bytes - HEADER_BYTES - size);
    uint8_t *dest = os_event_keep(event, size, out);
    if (dest == NULL) {
        at = wrap((uint16_t)at + size); /* dropped: the event was unregistered meanwhile */
        os.stats.events_discarded++;
    } else {
        for (uint8_t n = size; n != 0; n--) {
            *dest++ = ring[at];
            at = after(at);
        }
    }
    head = at;
    return dest != NULL;
}
