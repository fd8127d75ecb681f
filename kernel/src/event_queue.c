/* The queue of sent, not yet dispatched event occurrences.
 *
 * The oldest one is usually held in place: when a send finds the queue
 * empty, its data goes straight into the event's kept data and only the
 * event id is noted (os.held_event). That is the common case - an interrupt
 * sends, the dispatch follows at its end - and it copies the data once
 * instead of into the ring and out again.
 *
 * The others wait in one byte ring of [event id][size][data...] records,
 * so an occurrence costs two bytes plus its data and no fixed-size slot is
 * wasted. Ring records are always younger than the held one: a send holds
 * its occurrence only when the ring is empty too. Sends push with
 * interrupts masked; only the system thread pops. */
#include "kernel_internal.h"

#define QUEUE_BYTES ((uint8_t)OS_CFG_EVENT_QUEUE_BYTES)
#define HEADER_BYTES 2u
#define NOTHING_HELD 0u /* os.held_event is the held event's id + 1 */

static uint8_t ring[OS_CFG_EVENT_QUEUE_BYTES];
static uint8_t head; /* next byte to pop; os.queued_bytes follow it */
static uint8_t tail; /* next byte to push: head + os.queued_bytes, wrapped */

/* os.queued_bytes and os.held_event are cleared with the rest of os. */
void os_event_queue_reset(void) { head = tail = 0; }

/* The ring index after i. */
static inline uint8_t after(uint8_t i) {
    if (++i == QUEUE_BYTES) i = 0;
    return i;
}

/* One byte in at the tail, one out at the head: out of line, as the ring
 * is the uncommon path (the held occurrence is the common one), so a call
 * per byte costs less flash than the wrap test inline at every use. */
static OS_COLD void put(uint8_t byte) {
    ring[tail] = byte;
    tail = after(tail);
}

static OS_COLD uint8_t get(void) {
    uint8_t byte = ring[head];
    head = after(head);
    return byte;
}

/* The occurrence becomes the event's kept data now, if the queue is empty
 * and no handler of the event is reading its kept data. */
static OS_HOT bool hold(sys_event_id event, os_event_slot *slot, const void *data, uint8_t size) {
    uint8_t id_plus_one = (uint8_t)(event + 1u); /* 8-bit: no int promotion */
    if ((os.queued_bytes | os.held_event) != 0 || os.handling_event == id_plus_one) return false;
    slot->size = size;
    uint8_t *dest = slot->data;
    const uint8_t *src = (const uint8_t *)data;
    for (uint8_t n = size; n != 0; n--) *dest++ = *src++; /* a few bytes: no memcpy call */
    os.held_event = id_plus_one;
    return true;
}

/* Out of line, so the common case - held - is a leaf that saves no
 * registers. 8-bit arithmetic throughout: the ring and a record (2 + at
 * most 253 bytes) fit in 8 bits. The count goes up before the bytes go in
 * (interrupts are masked), so it is not kept across the calls. */
static OS_COLD sys_status push_or_refuse(sys_event_id event, const void *data, uint8_t size) {
    uint8_t record = (uint8_t)(HEADER_BYTES + size);
    uint8_t used = os.queued_bytes;
    uint8_t room = (uint8_t)(QUEUE_BYTES - used); /* a variable: with 255 bytes, GCC sees ~used */
    if (record > room) {
        os_count(&os_stats.event_queue_full);
        return SYS_E_QUEUE_FULL;
    }
    used = (uint8_t)(used + record);
    os.queued_bytes = used;
    if (used > os_stats.event_queue_peak) os_stats.event_queue_peak = used;
    put(event);
    put(size);
    const uint8_t *src = (const uint8_t *)data;
    for (uint8_t n = size; n != 0; n--) put(*src++);
    return SYS_OK;
}

sys_status os_event_post(sys_event_id event, const void *data, uint8_t size) {
    os_event_slot *slot = &os_events[event];
    if (slot->size == OS_EVENT_UNREGISTERED) return SYS_E_NOT_REGISTERED;
    if (size > slot->capacity) return SYS_E_TOO_BIG;
    os.reconsider = true; /* the system thread has work (or nothing changed: harmless) */
    if (hold(event, slot, data, size)) return SYS_OK;
    return push_or_refuse(event, data, size);
}

static OS_HOT void describe(sys_event_id event, const os_event_slot *slot, sys_event_data *out) {
    out->value = slot->data;
    out->size = slot->size;
    out->event = event;
}

/* The occurrence at the ring's head becomes its event's kept data, unless
 * it no longer fits: the event was unregistered (or registered again
 * smaller) since it was sent. Its event's id + 1, or NOTHING_HELD if it had
 * to be discarded. Out of line: the held occurrence is the common case, and
 * the ring's index kept in a register across the dispatch loop cost it 4
 * cycles (bench/avr_bench.py). */
static OS_COLD uint8_t pop_ring(void) {
    sys_event_id event = get();
    uint8_t size = get();
    os.queued_bytes = (uint8_t)(os.queued_bytes - HEADER_BYTES - size);
    os_event_slot *slot = &os_events[event]; /* the ring only holds ids that were valid */
    if (slot->size == OS_EVENT_UNREGISTERED || size > slot->capacity) {
        for (uint8_t n = size; n != 0; n--) get(); /* skipped */
        os_count(&os_stats.events_discarded);
        return NOTHING_HELD;
    }
    slot->size = size;
    uint8_t *dest = slot->data;
    for (uint8_t n = size; n != 0; n--) *dest++ = get();
    return (uint8_t)(event + 1u);
}

bool os_event_queue_pop(sys_event_data *out) {
    uint8_t id_plus_one = os.held_event;
    if (id_plus_one == NOTHING_HELD && (id_plus_one = pop_ring()) == NOTHING_HELD) return false;
    os.held_event = NOTHING_HELD;
    sys_event_id event = (sys_event_id)(id_plus_one - 1u);
    describe(event, &os_events[event], out);
    return true;
}

void os_event_queue_forget(sys_event_id event) {
    if (!os_event_queue_holds(event)) return;
    os.held_event = NOTHING_HELD; /* its kept data goes with the registration */
    os_count(&os_stats.events_discarded);
}
