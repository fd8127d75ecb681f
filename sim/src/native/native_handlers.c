/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* A handler subscribed and never called, in the native mode
 * (native_handlers.h). The kernel tells the native port of every handler
 * it calls (PORT_HANDLER_CALLED), which notes each function once in the
 * robot's native_io; the subscriptions are the kernel's static subs array,
 * found by symbol in the shared object and read from the robot's RAM
 * image. Handlers are named by the object's own symbols and debug lines
 * (addr2line): its dynamic symbols are the entry alone (robot.map), so
 * dladdr names none. The kernel's and kilolib's own handlers are left
 * out, as in the exact mode. */
#define _GNU_SOURCE
#include "native/native_handlers.h"

#include <dlfcn.h>
#include <gelf.h>
#include <stdint.h>
#include <string.h>

#include "native/native_swarm.h"

/* The kernel's struct subscription on the host (kernel/src/event_table.c):
 * the handler, its condition or binding, the event, the thread. */
typedef struct host_subscription {
    uintptr_t handler, with;
    uint8_t event, pid;
} host_subscription;

/* Offsets into the shared object; 0: not found. */
typedef struct object_handlers {
    uint32_t subs, subs_size, subs_end, subs_end_size;
    uint32_t bound; /* the kernel's trampoline for bindings */
} object_handlers;

static void note_symbol(const char *name, uint32_t value, uint32_t size, int type, void *ctx) {
    object_handlers *s = ctx;
    if (name == NULL) return;
    if (type == STT_OBJECT && symbol_named(name, "subs")) {
        s->subs = value;
        s->subs_size = size;
    } else if (type == STT_OBJECT && symbol_named(name, "subs_end")) {
        s->subs_end = value;
        s->subs_end_size = size;
    } else if (type == STT_FUNC && symbol_named(name, "bound")) {
        s->bound = value;
    }
}

static object_handlers handlers_of(const char *so) {
    static const char *read_path;
    static object_handlers handlers;
    firmware_symbols_once(so, &read_path, note_symbol, &handlers, sizeof handlers);
    return handlers;
}

/* n bytes robot index's code reads at address: its RAM or stacks, or the
 * object's constants; NULL elsewhere. */
static const void *readable(int index, uintptr_t address, size_t n) {
    const void *at = native_swarm_robot_memory(index, (const void *)address, n);
    if (at != NULL) return at;
    Dl_info info;
    if (dladdr((const void *)address, &info) == 0 || (uintptr_t)info.dli_fbase != native_swarm_copy_of(index)->base)
        return NULL;
    return (const void *)address;
}

/* The function a subscription calls, an address; 0: none to judge. */
static uintptr_t called_function(int index, const host_subscription *sub, uintptr_t bound) {
    if (sub->handler == 0) return 0; /* unsubscribed, not yet packed away */
    if (sub->handler != bound) return sub->handler;
    /* a sys_event_binding, whose handler comes first */
    const uintptr_t *binding = readable(index, sub->with, sizeof *binding);
    return binding != NULL ? *binding : 0;
}

static int called(const native_io *io, uintptr_t function) {
    for (unsigned i = 0; i < io->n_handlers_called; i++)
        if (io->handlers_called[i] == function) return 1;
    return 0;
}

/* Where a handler is and its name: asked of addr2line once per function
 * of an app, whatever the number of robots (a thousand robots share their
 * handlers; apps of one world share offsets, not functions). */
typedef struct handler_place {
    const char *so;
    uintptr_t offset;
    char place[400], name[128];
} handler_place;

static const handler_place *place_of(const char *so, uintptr_t offset) {
    static handler_place known[16];
    static unsigned n_known, next;
    for (unsigned i = 0; i < n_known; i++)
        if (known[i].offset == offset && strcmp(known[i].so, so) == 0) return &known[i];
    handler_place *p = &known[next];
    next = (next + 1) % (sizeof known / sizeof *known);
    if (n_known < sizeof known / sizeof *known) n_known++;
    p->so = so;
    p->offset = offset;
    host_code_place(so, offset, p->place, sizeof p->place, p->name, sizeof p->name);
    return p;
}

int native_handlers_report(int index, int robot_index, robot_kind kind, const char *so, double seconds) {
    const native_io *io = native_swarm_robot(index)->io;
    object_handlers h = handlers_of(so);
    if (h.subs == 0 || h.subs_end == 0 || h.subs_size % sizeof(host_subscription) != 0 ||
        h.subs_end_size != sizeof(uintptr_t) || io->handlers_called_full)
        return 0; /* a kernel of another layout, or more handlers called than noted: unknown */
    uintptr_t base = native_swarm_copy_of(index)->base;
    const uintptr_t *end_at = readable(index, base + h.subs_end, sizeof *end_at);
    const uint8_t *subs = readable(index, base + h.subs, h.subs_size);
    if (end_at == NULL || subs == NULL) return 0;
    uintptr_t first = base + h.subs, end = *end_at;
    if (end < first || end > first + h.subs_size) return 0; /* not a pointer into subs: unknown */
    int warnings = 0;
    for (uintptr_t at = first; at + sizeof(host_subscription) <= end; at += sizeof(host_subscription)) {
        host_subscription sub;
        memcpy(&sub, subs + (at - first), sizeof sub);
        uintptr_t function = called_function(index, &sub, h.bound != 0 ? base + h.bound : 0);
        if (function == 0 || called(io, function)) continue;
        const handler_place *p = place_of(so, function - base);
        if (handler_watch_library_name(p->name)) continue;
        char event[96];
        handler_never_called_note(robot_index, p->place, event_name(so, kind, sub.event, event, sizeof event),
                                  sub.pid, seconds);
        warnings++;
    }
    return warnings;
}
