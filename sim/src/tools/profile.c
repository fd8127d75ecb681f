/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* --profile: where the CPU cycles go, by function. Each instruction's
 * cycles (an interrupt's entry included) are charged to the function that
 * holds it, found in the ELF's symbol table; cycles spent asleep are
 * counted apart. The table is printed when the run ends. */
#include <gelf.h>
#include <stdlib.h>
#include <string.h>

#include "sim.h"

#define SHOWN 25

typedef struct function {
    uint32_t start, end; /* byte addresses in flash */
    char *name;
    uint64_t cycles;
} function;

static function *functions;
static size_t n_functions;
static uint64_t asleep, elsewhere;

static int by_start(const void *a, const void *b) {
    const function *x = a, *y = b;
    return x->start < y->start ? -1 : x->start > y->start;
}

static int by_cycles(const void *a, const void *b) {
    const function *x = a, *y = b;
    return x->cycles > y->cycles ? -1 : x->cycles < y->cycles;
}

static size_t room;

static void add_function(const char *name, uint32_t value, uint32_t size, int type, void *ctx) {
    (void)ctx;
    if ((type != STT_FUNC && type != STT_NOTYPE) || size == 0) return; /* asm routines are often untyped */
    if (n_functions == room) {
        size_t more = room ? 2 * room : 256;
        function *grown = realloc(functions, more * sizeof *functions);
        if (grown == NULL) return;
        functions = grown;
        room = more;
    }
    function *f = &functions[n_functions++];
    f->start = value;
    f->end = value + size;
    f->name = strdup(name != NULL ? name : "?");
    f->cycles = 0;
}

int profile_load(const char *path) {
    if (firmware_symbols(path, add_function, NULL) != 0) {
        fprintf(stderr, "openswarm-sim: --profile: cannot read the symbols of %s\n", path);
        return -1;
    }
    qsort(functions, n_functions, sizeof *functions, by_start);
    return 0;
}

static function *function_at(uint32_t pc) {
    size_t lo = 0, hi = n_functions;
    while (lo < hi) { /* the last function starting at or before pc */
        size_t mid = (lo + hi) / 2;
        if (functions[mid].start <= pc)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo > 0 && pc < functions[lo - 1].end ? &functions[lo - 1] : NULL;
}

void profile_charge(uint32_t pc, int was_asleep, uint64_t cycles) {
    function *f = was_asleep ? NULL : function_at(pc);
    if (was_asleep)
        asleep += cycles;
    else if (f != NULL)
        f->cycles += cycles;
    else
        elsewhere += cycles;
}

void profile_print(int robots) {
    uint64_t total = asleep + elsewhere;
    for (size_t i = 0; i < n_functions; i++) total += functions[i].cycles;
    qsort(functions, n_functions, sizeof *functions, by_cycles);
    fprintf(stderr, "openswarm-sim: profile of %llu cycles%s, by function:\n",
            (unsigned long long)total, robots > 1 ? " (all robots)" : "");
    fprintf(stderr, "  %12s %6s  %s\n", "cycles", "share", "function");
    double pct = total ? 100.0 / (double)total : 0.0;
    fprintf(stderr, "  %12llu %5.1f%%  (asleep)\n", (unsigned long long)asleep, asleep * pct);
    for (size_t i = 0; i < n_functions && i < SHOWN && functions[i].cycles != 0; i++)
        fprintf(stderr, "  %12llu %5.1f%%  %s\n", (unsigned long long)functions[i].cycles,
                functions[i].cycles * pct, functions[i].name);
    if (elsewhere != 0)
        fprintf(stderr, "  %12llu %5.1f%%  (outside any function: vectors, start-up)\n",
                (unsigned long long)elsewhere, elsewhere * pct);
}
