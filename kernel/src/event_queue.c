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

/* Copy n bytes into the ring at `at`, wrapping once if needed. */
static void ring_write(uint8_t at, const uint8_t *src, uint8_t n) {
    uint8_t *dst = &ring[at];
    while (n-- != 0) {
        *dst++ = *src++;
        if (dst == &ring[QUEUE_BYTES]) dst = ring;
    }
}

static uint8_t wrap(uint16_t index) {
    return (uint8_t)(index >= QUEUE_BYTES ? index - QUEUE_BYTES : index);
}

bool os_event_queue_push(sys_event_id event, const void *data, uint8_t size) {
    if ((uint16_t)os.queued_bytes + HEADER_BYTES + size > QUEUE_BYTES) return false;
    uint8_t header[HEADER_BYTES] = {event, size};
    uint8_t tail = wrap((uint16_t)head + os.queued_bytes);
    ring_write(tail, header, HEADER_BYTES);
    ring_write(wrap((uint16_t)tail + HEADER_BYTES), (const uint8_t *)data, size);
    os.queued_bytes = (uint8_t)(os.queued_bytes + HEADER_BYTES + size);
    if (os.queued_bytes > os.stats.event_queue_peak) os.stats.event_queue_peak = os.queued_bytes;
    return true;
}

/* Take n bytes from the head into dest (NULL: drop them). */
static void ring_read(uint8_t *dest, uint8_t n) {
    const uint8_t *src = &ring[head];
    os.queued_bytes = (uint8_t)(os.queued_bytes - n);
    while (n-- != 0) {
        uint8_t byte = *src++;
        if (src == &ring[QUEUE_BYTES]) src = ring;
        if (dest != NULL) *dest++ = byte;
    }
    head = (uint8_t)(src - ring);
}

static uint8_t take_byte(void) {
    uint8_t byte = ring[head];
    head = (uint8_t)(head + 1u == QUEUE_BYTES ? 0u : head + 1u);
    os.queued_bytes--;
    return byte;
}

bool os_event_queue_pop(sys_event_data *out) {
    sys_event_id event = take_byte();
    uint8_t size = take_byte();
    bool deliverable = os_event_registered(event) && size <= os_event_capacity(event);
    ring_read(deliverable ? os_event_buffer(event) : NULL, size);
    if (!deliverable) {
        os.stats.events_discarded++;
        return false;
    }
    return os_event_store(event, size, out);
}
