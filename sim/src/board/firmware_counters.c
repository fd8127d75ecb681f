/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* --counters PERIOD: every robot's firmware counters, read from its RAM
 * by the symbols' names, as one line each:
 *   counters t=SECONDS robot=INDEX process_pool_full=0 ... event_queue_peak=12
 *     ir_sent=310 ... main_stack=180/1024 thread_stacks=57/120,33/88
 * The kernel's resource counters are os_stats (sys_stats, kernel/include/
 * openswarm/fault.h: twelve 16-bit counters, then the queue's peak byte),
 * the Kilobot IR driver's ir_stats (kilobot_ir_stats: seven 16-bit
 * counters); a firmware without one of them (a classic-library build)
 * shows "none" for it, one with another layout "unknown layout". The
 * thread stacks are thread_stacks.c's, used/room each, by address. The
 * firmware is not stopped or asked: the simulator reads between windows. */
#include <string.h>

#include "sim.h"

static const char *const kernel_names[] = {
    "process_pool_full", "stack_pool_full", "event_data_full", "subscription_pool_full",
    "event_queue_full", "device_table_full", "events_discarded", "stack_overflows",
    "critical_leaks", "cpu_faults", "handler_overruns", "subscriptions_refused"};
#define KERNEL_COUNTERS (sizeof kernel_names / sizeof kernel_names[0])
#define KERNEL_BYTES (2 * KERNEL_COUNTERS + 1) /* and event_queue_peak */

static const char *const ir_names[KILOBOT_IR_COUNTERS] = {"sent", "received", "refused", "bad_crc",
                                                           "broken", "collisions", "busy"};
#define IR_COUNTERS KILOBOT_IR_COUNTERS

typedef struct counter_symbols counter_symbols;

static void note_symbol(const char *name, uint32_t value, uint32_t size, int type, void *ctx) {
    (void)type;
    counter_symbols *s = ctx;
    if (name == NULL || value < AVR_DATA_OFFSET) return;
    if (symbol_named(name, "os_stats")) {
        s->kernel = value - AVR_DATA_OFFSET;
        s->kernel_size = size;
    } else if (symbol_named(name, "kilobot_ir_counters")) {
        s->ir = value - AVR_DATA_OFFSET;
        s->ir_size = size;
    } else if (symbol_named(name, "os_stack_pool")) {
        s->stack_pool = value - AVR_DATA_OFFSET;
        s->stack_pool_size = size;
    }
}

/* At load: the file may be rebuilt while the run goes on (the symbols of
 * another build would point into the wrong RAM). */
void firmware_counters_locate(robot *r, const char *elf_path) {
    memset(&r->counters, 0, sizeof r->counters);
    firmware_symbols(elf_path, note_symbol, &r->counters);
}

static unsigned u16_at(const avr_t *avr, uint32_t address) {
    return avr->data[address] | (unsigned)avr->data[address + 1] << 8;
}

static void print_kernel(FILE *out, const avr_t *avr, const counter_symbols *s) {
    if (s->kernel == 0) {
        fprintf(out, " kernel=none");
    } else if (s->kernel_size != KERNEL_BYTES || s->kernel + KERNEL_BYTES > avr->ramend + 1u) {
        fprintf(out, " kernel=unknown-layout");
    } else {
        for (unsigned i = 0; i < KERNEL_COUNTERS; i++)
            fprintf(out, " %s=%u", kernel_names[i], u16_at(avr, s->kernel + 2 * i));
        fprintf(out, " event_queue_peak=%u", avr->data[s->kernel + 2 * KERNEL_COUNTERS]);
    }
}

static int ir_layout_known(const avr_t *avr, const counter_symbols *s) {
    return s->ir_size == 2 * IR_COUNTERS && s->ir + 2 * IR_COUNTERS <= avr->ramend + 1u;
}

int firmware_ir_counters(const robot *r, uint16_t out[KILOBOT_IR_COUNTERS]) {
    const counter_symbols *s = &r->counters;
    if (s->ir == 0 || !ir_layout_known(r->avr, s)) return 0;
    for (unsigned i = 0; i < IR_COUNTERS; i++) out[i] = (uint16_t)u16_at(r->avr, s->ir + 2 * i);
    return 1;
}

static void print_ir(FILE *out, const robot *r) {
    uint16_t counts[KILOBOT_IR_COUNTERS];
    if (r->counters.ir == 0) {
        fprintf(out, " ir=none");
    } else if (!firmware_ir_counters(r, counts)) {
        fprintf(out, " ir=unknown-layout");
    } else {
        for (unsigned i = 0; i < IR_COUNTERS; i++) fprintf(out, " ir_%s=%u", ir_names[i], counts[i]);
    }
}

#define MAX_THREAD_STACKS 16 /* the kernel's OS_CFG_MAX_THREADS at most */

static void print_thread_stacks(FILE *out, const robot *r, const counter_symbols *s) {
    thread_stack stacks[MAX_THREAD_STACKS];
    int n = thread_stacks_read(r, s->stack_pool, s->stack_pool_size, stacks, MAX_THREAD_STACKS);
    fprintf(out, " thread_stacks=");
    if (n <= 0) fprintf(out, "none");
    for (int i = 0; i < n; i++) fprintf(out, "%s%u/%u", i ? "," : "", stacks[i].used, stacks[i].room);
}

void firmware_counters_print(const robot *r, double seconds) {
    const counter_symbols s = r->counters;
    unsigned room, used = main_stack_worst(r, &room);
    printf("counters t=%.3f robot=%d", seconds, r->index);
    print_kernel(stdout, r->avr, &s);
    print_ir(stdout, r);
    if (room != 0)
        printf(" main_stack=%u/%u", used, room);
    else
        printf(" main_stack=unmeasured");
    print_thread_stacks(stdout, r, &s);
    printf("\n");
}
