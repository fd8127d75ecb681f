/* What only the Cortex-M4 port has: the FPU context of preempted
 * threads, and CPU faults caught in a thread. Run under QEMU
 * (qemu.cm4_suite). */
#include "openswarm/kernel.h"
#include "openswarm/port.h"
#include "test_target.h"

#include <stdbool.h>

static uint16_t passed, failed;

#define CHECK(cond) check((cond), __LINE__)
static void check(bool ok, uint16_t line) {
    if (ok) {
        passed++;
        return;
    }
    failed++;
    target_puts("  FAIL at cm4_suite.c:");
    target_put_uint(line);
    target_putc('\n');
}

/* ---- every FPU register survives preemption ----
 * Each thread fills s0-s31 with its own pattern, spins through several
 * time slices (preempted by the tick, the other FPU thread running in
 * between), then compares: s0-s15 come back from the exception frame
 * (lazily stacked), s16-s31 from the switch frame. */
static volatile uint32_t fpu_mismatches[2], fpu_rounds[2];

static void fill_and_check(uint32_t seed, volatile uint32_t *mismatches) {
    float expected[32], actual[32];
    for (unsigned i = 0; i < 32; i++) expected[i] = (float)(seed * 100u + i);
    __asm__ __volatile__("vldm %0, {s0-s31}" ::"r"(expected) : "memory");
    for (volatile uint32_t spin = 0; spin < 40000u; spin++) {
    }
    __asm__ __volatile__("vstm %0, {s0-s31}" ::"r"(actual) : "memory");
    for (unsigned i = 0; i < 32; i++)
        if (actual[i] != expected[i]) (*mismatches)++;
}

static void fpu_thread(void *arg) {
    uint32_t which = (uint32_t)(uintptr_t)arg;
    for (uint32_t round = 0; round < 20u; round++) {
        fill_and_check(which + 1u + round * 2u, &fpu_mismatches[which]);
        fpu_rounds[which]++;
    }
}

static volatile uint32_t integer_spins;
static void integer_thread(void *arg) {
    (void)arg;
    for (;;) integer_spins++;
}

static void fpu_control(void *arg) {
    (void)arg;
    uint32_t switches0 = Sys_Get_SwitchCount();
    while (fpu_rounds[0] < 20u || fpu_rounds[1] < 20u) Sys_Sleep(5);
    CHECK(fpu_mismatches[0] == 0 && fpu_mismatches[1] == 0);
    CHECK(integer_spins > 0);
    CHECK(Sys_Get_SwitchCount() - switches0 > 20u); /* they were preempted */
    Sys_Stop_Kernel();
}

static void fpu_setup(void) {
    Sys_Start_Process_Ex(fpu_control, NULL, 256, 0, NULL);
    Sys_Start_Process_Ex(fpu_thread, (void *)0, 512, 0, NULL);
    Sys_Start_Process_Ex(fpu_thread, (void *)1, 512, 0, NULL);
    Sys_Start_Process_Ex(integer_thread, NULL, 0, 0, NULL);
}

/* ---- a CPU fault ends the thread, not the robot ---- */
static volatile uint8_t fault_seen, faults;
static volatile sys_pid fault_pid;
static void on_fault(sys_fault f, sys_pid pid) {
    fault_seen = (uint8_t)f;
    fault_pid = pid;
    faults++;
}

static volatile int divisor; /* 0, unknown to the compiler */
static volatile int after_fault;

static void divides_by_zero(void *arg) {
    (void)arg;
    after_fault = 100 / divisor;
    after_fault = 1; /* never */
}
static void undefined_instruction(void *arg) {
    (void)arg;
    __asm__ __volatile__("udf #0");
    after_fault = 1;
}
static void bad_address(void *arg) {
    (void)arg;
    after_fault = *(volatile int *)0xE0100000u; /* nothing there: a bus fault */
    after_fault = 1;
}

static void expect_fault_ends(sys_process_fn culprit, uint8_t nth) {
    sys_pid pid;
    CHECK(Sys_Start_Process_Ex(culprit, NULL, 0, 0, &pid) == SYS_OK);
    Sys_Sleep(2);
    CHECK(faults == nth);
    CHECK(fault_seen == SYS_FAULT_CPU);
    CHECK(fault_pid == pid);
    CHECK(Sys_Get_ProcessState(pid, NULL) == SYS_E_INVALID); /* ended and reaped */
    CHECK(after_fault == 0);
}

static void fault_control(void *arg) {
    (void)arg;
    expect_fault_ends(divides_by_zero, 1);
    expect_fault_ends(undefined_instruction, 2);
    expect_fault_ends(bad_address, 3);
    sys_stats s;
    Sys_Get_Stats(&s);
    CHECK(s.cpu_faults == 3);
    Sys_Sleep(2); /* the tick and this thread go on */
    Sys_Stop_Kernel();
}

static void fault_setup(void) {
    faults = 0;
    Sys_Set_FaultHook(on_fault);
    Sys_Start_Process_Ex(fault_control, NULL, 256, 0, NULL);
}

/* ---- the runner ---- */
static void run(const char *name, void (*setup)(void)) {
    uint16_t failed_before = failed;
    Sys_Init_Kernel();
    setup();
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    target_puts(failed == failed_before ? "ok   " : "FAIL ");
    target_puts(name);
    target_putc('\n');
}

int main(void) {
    target_init();
    run("fpu_context", fpu_setup);
    run("cpu_fault_in_thread", fault_setup);
    target_put_uint(passed);
    target_puts(" passed, ");
    target_put_uint(failed);
    target_puts(" failed\n");
    target_exit(failed == 0 ? 0 : 1);
}

void target_interrupt(int16_t value) { (void)value; }
