/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* A handler subscribed and never called: at the end of a run, each
 * subscription still in the kernel's table (its static subs array, found
 * by symbol) whose handler's first instruction never ran. The simulator
 * notes every instruction's address as it runs (handler_watch_step, a bit
 * per flash word); the kernel counts nothing per subscription, as a count
 * would cost flash the classic Kilobot programs have not to spare
 * (avr.kilolib_budget). A subscription with a context names its binding,
 * whose function is the one looked for. The handlers the kernel and the
 * kilolib layer subscribe for themselves are not the app's concern and
 * are left out: the HAL's command_handler (an output device's commands,
 * which a program that sets its LED directly never sends) and kilolib_*
 * (the messages the program may never get, its calls). */
#include <gelf.h>
#include <stdlib.h>
#include <string.h>

#include "sim.h"

/* The kernel's struct subscription on the ATmega328P (event_table.c):
 * handler (a word address), condition or binding, event, pid. */
#define SUBSCRIPTION_BYTES 6

/* The kernel's and the kilolib layer's own handlers (kernel/src/hal.c,
 * ports/kilobot/kilolib/src/kilolib.c). */
static const char *const library_handler_names[] = {"command_handler", "kilolib_deliver_message",
                                                    "kilolib_run_call"};
#define MAX_LIBRARY_HANDLERS (sizeof library_handler_names / sizeof library_handler_names[0])

typedef struct image_handlers {
    uint32_t subs, subs_size, subs_end; /* data-space addresses; 0: no kernel */
    uint32_t bound;                     /* the kernel's trampoline for bindings, a byte address */
    uint32_t library[MAX_LIBRARY_HANDLERS]; /* byte addresses; 0: not in this image */
} image_handlers;

_Static_assert(MAX_LIBRARY_HANDLERS == sizeof ((handler_watch *)0)->library / sizeof(uint32_t),
               "sim.h's handler_watch keeps one address per library handler");

static void note_symbol(const char *name, uint32_t value, uint32_t size, int type, void *ctx) {
    image_handlers *s = ctx;
    if (name == NULL) return;
    if (symbol_named(name, "subs") && value >= AVR_DATA_OFFSET) {
        s->subs = value - AVR_DATA_OFFSET;
        s->subs_size = size;
    } else if (symbol_named(name, "subs_end") && value >= AVR_DATA_OFFSET) {
        s->subs_end = value - AVR_DATA_OFFSET;
    } else if (type == STT_FUNC && symbol_named(name, "bound")) {
        s->bound = value;
    } else if (type == STT_FUNC) {
        for (size_t i = 0; i < MAX_LIBRARY_HANDLERS; i++)
            if (symbol_named(name, library_handler_names[i])) s->library[i] = value;
    }
}

static image_handlers handlers_of(const char *elf_path) {
    static const char *read_path;
    static image_handlers handlers;
    firmware_symbols_once(elf_path, &read_path, note_symbol, &handlers, sizeof handlers);
    return handlers;
}

void handler_watch_attach(robot *r, const char *elf_path) {
    handler_watch *w = &r->handler_watch;
    free(w->ran);
    free(w->elf);
    memset(w, 0, sizeof *w);
    image_handlers s = handlers_of(elf_path);
    if (s.subs == 0 || s.subs_end == 0 || s.subs_size % SUBSCRIPTION_BYTES != 0 ||
        s.subs + s.subs_size > r->avr->ramend + 1u || s.subs_end + 2u > r->avr->ramend + 1u)
        return; /* no OpenSwarm kernel, or one of another layout */
    /* The path is copied: a world's firmware paths are freed with the
     * world, before the end-of-run report names the handlers. */
    w->ran = calloc(r->avr->flashend / 16u + 1u, 1);
    w->elf = strdup(elf_path);
    if (w->ran == NULL || w->elf == NULL) { /* unwatched: the warning is the only loss */
        free(w->ran);
        free(w->elf);
        memset(w, 0, sizeof *w);
        return;
    }
    w->subs = s.subs;
    w->subs_size = s.subs_size;
    w->subs_end = s.subs_end;
    w->bound = s.bound;
    memcpy(w->library, s.library, sizeof w->library);
}

static unsigned u16_at(const avr_t *avr, uint32_t address) {
    return address + 1u <= avr->ramend ? avr->data[address] | (unsigned)avr->data[address + 1] << 8 : 0;
}

static int ran(const handler_watch *w, uint32_t byte_address) {
    return (w->ran[byte_address >> 4] >> ((byte_address >> 1) & 7u)) & 1u;
}

static int library_handler(const handler_watch *w, uint32_t byte_address) {
    for (size_t i = 0; i < MAX_LIBRARY_HANDLERS; i++)
        if (w->library[i] == byte_address) return 1;
    return 0;
}

/* The function a subscription calls, a byte address; 0: none to judge. */
static uint32_t called_function(const robot *r, uint32_t entry) {
    const handler_watch *w = &r->handler_watch;
    uint32_t handler = 2u * u16_at(r->avr, entry);
    if (handler == 0) return 0; /* unsubscribed, not yet packed away */
    if (handler == w->bound) handler = 2u * u16_at(r->avr, u16_at(r->avr, entry + 2u));
    if (handler > r->avr->flashend || library_handler(w, handler)) return 0;
    return handler;
}

int handler_watch_library_name(const char *name) {
    for (size_t i = 0; i < MAX_LIBRARY_HANDLERS; i++)
        if (symbol_named(name, library_handler_names[i])) return 1;
    return 0;
}

void handler_never_called_note(int robot_index, const char *place, const char *event, unsigned pid,
                               double seconds) {
    warning_note(robot_index, "the handler %s, subscribed to %s on thread %u, was never called in "
                 "%.3f s: no occurrence of the event reached it (nothing sent it, its device was not "
                 "started, or its condition refused each one); send the event, run longer, or "
                 "unsubscribe a handler the app does not need",
                 place, event, pid, seconds);
}

int handler_watch_report(const robot *r, int robot_index) {
    const handler_watch *w = &r->handler_watch;
    if (w->ran == NULL) return 0;
    uint32_t end = u16_at(r->avr, w->subs_end);
    if (end < w->subs || end > w->subs + w->subs_size) return 0; /* not a pointer into subs: unknown */
    double t = (double)r->avr->cycle / r->avr->frequency;
    int warnings = 0;
    for (uint32_t entry = w->subs; entry + SUBSCRIPTION_BYTES <= end; entry += SUBSCRIPTION_BYTES) {
        uint32_t handler = called_function(r, entry);
        if (handler == 0 || ran(w, handler)) continue;
        char place[400], event[96];
        handler_never_called_note(robot_index, code_place(w->elf, handler, place, sizeof place),
                                  event_name(w->elf, ROBOT_KILOBOT, r->avr->data[entry + 4u], event, sizeof event),
                                  r->avr->data[entry + 5u], t);
        warnings++;
    }
    return warnings;
}
