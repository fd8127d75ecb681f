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

/* Little-endian on the robot and on the host (x86-64, arm64): the
 * native mode's counters read the same way. */
static unsigned u16_at(const uint8_t *bytes) { return bytes[0] | (unsigned)bytes[1] << 8; }

void firmware_counters_print_kernel(FILE *out, const uint8_t *bytes, int layout_known) {
    if (bytes == NULL) {
        fprintf(out, " kernel=none");
    } else if (!layout_known) {
        fprintf(out, " kernel=unknown-layout");
    } else {
        for (unsigned i = 0; i < KERNEL_COUNTERS; i++) fprintf(out, " %s=%u", kernel_names[i], u16_at(bytes + 2 * i));
        fprintf(out, " event_queue_peak=%u", bytes[2 * KERNEL_COUNTERS]);
    }
}

void firmware_counters_print_ir(FILE *out, const uint8_t *bytes, int layout_known) {
    if (bytes == NULL) {
        fprintf(out, " ir=none");
    } else if (!layout_known) {
        fprintf(out, " ir=unknown-layout");
    } else {
        for (unsigned i = 0; i < IR_COUNTERS; i++) fprintf(out, " ir_%s=%u", ir_names[i], u16_at(bytes + 2 * i));
    }
}

/* n bytes of avr's RAM at address (0: the firmware has no such symbol),
 * and whether they lie in its RAM and the symbol's size is n. */
static const uint8_t *counters_at(const avr_t *avr, uint32_t address, uint32_t size, uint32_t n, int *fits) {
    *fits = size == n && address + n <= avr->ramend + 1u;
    return address == 0 ? NULL : avr->data + address;
}

int firmware_ir_counters(const robot *r, uint16_t out[KILOBOT_IR_COUNTERS]) {
    int fits;
    const uint8_t *bytes = counters_at(r->avr, r->counters.ir, r->counters.ir_size, 2 * IR_COUNTERS, &fits);
    if (bytes == NULL || !fits) return 0;
    for (unsigned i = 0; i < IR_COUNTERS; i++) out[i] = (uint16_t)u16_at(bytes + 2 * i);
    return 1;
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
    int fits;
    printf("counters t=%.3f robot=%d", seconds, r->index);
    const uint8_t *kernel = counters_at(r->avr, s.kernel, s.kernel_size, KERNEL_BYTES, &fits);
    firmware_counters_print_kernel(stdout, kernel, fits);
    const uint8_t *ir = counters_at(r->avr, s.ir, s.ir_size, 2 * IR_COUNTERS, &fits);
    firmware_counters_print_ir(stdout, ir, fits);
    if (room != 0)
        printf(" main_stack=%u/%u", used, room);
    else
        printf(" main_stack=unmeasured");
    print_thread_stacks(stdout, r, &s);
    printf("\n");
}
