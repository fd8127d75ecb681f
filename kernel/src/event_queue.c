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

static void put(uint8_t byte) {
    uint16_t at = (uint16_t)(head + os.queued_bytes);
    ring[at >= QUEUE_BYTES ? at - QUEUE_BYTES : at] = byte;
    os.queued_bytes++;
}

static uint8_t take(void) {
    uint8_t byte = ring[head];
    head = (uint8_t)(head + 1u == QUEUE_BYTES ? 0u : head + 1u);
    os.queued_bytes--;
    return byte;
}

bool os_event_queue_push(sys_event_id event, const void *data, uint8_t size) {
    if ((uint16_t)os.queued_bytes + HEADER_BYTES + size > QUEUE_BYTES) return false;
    const uint8_t *bytes = (const uint8_t *)data;
    put(event);
    put(size);
    for (uint8_t i = 0; i < size; i++) put(bytes[i]);
    if (os.queued_bytes > os.stats.event_queue_peak) os.stats.event_queue_peak = os.queued_bytes;
    return true;
}

bool os_event_queue_pop(sys_event_data *out) {
    sys_event_id event = take();
    uint8_t size = take();
    bool deliverable = os_event_registered(event) && size <= os_event_capacity(event);
    uint8_t *dest = deliverable ? os_event_buffer(event) : NULL;
    for (uint8_t i = 0; i < size; i++) {
        uint8_t byte = take();
        if (dest != NULL) dest[i] = byte;
    }
    if (!deliverable) {
        os.stats.events_discarded++;
        return false;
    }
    return os_event_store(event, size, out);
}
