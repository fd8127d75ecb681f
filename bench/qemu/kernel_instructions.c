/* Instruction counts of the kernel's hot paths on the Cortex-M4, under
 * QEMU with -icount shift=0: every instruction is one nanosecond of
 * virtual time, and TIM2 (QEMU 7.2 counts it at 1 GHz of virtual time) is
 * an instruction counter. Each sample is printed as "<what> <count>";
 * bench/qemu_bench.py takes the medians. A sample runs from the counter
 * read before the operation to the first read after it in the other
 * context (the reads included: 2-3 instructions). QEMU counts
 * instructions, not cycles: a real STM32F407 adds wait states, pipeline
 * refills and exception entry cycles. */
#include "openswarm/cortex_m4.h"
#include "openswarm/kernel.h"
#include "openswarm/port.h"

#define TIM2_CR1 (*(volatile uint32_t *)0x40000000u)
#define TIM2_CNT (*(volatile uint32_t *)0x40000024u)
#define TIM2_PSC (*(volatile uint32_t *)0x40000028u)
#define TIM2_ARR (*(volatile uint32_t *)0x4000002Cu)
#define NVIC_STIR (*(volatile uint32_t *)0xE000EF00u)
#define EXTI0_IRQ 6
#define EV (SYS_EVENT_FIRST_FREE)
#define SAMPLES 100u

static inline uint32_t now(void) { return TIM2_CNT; }

/* Samples are kept and printed after each phase: printing takes long
 * enough for a tick to fall in it, which would hide switches. */
static struct {
    const char *what;
    uint32_t count;
} samples[2 * SAMPLES];
static unsigned sample_count;

static void sample(const char *what, uint32_t count) {
    if (sample_count < sizeof samples / sizeof samples[0])
        samples[sample_count++] = (typeof(samples[0])){what, count};
}

static void print_samples(void) {
    for (unsigned i = 0; i < sample_count; i++) {
        cortex_m4_print(samples[i].what);
        cortex_m4_print(" ");
        cortex_m4_print_uint(samples[i].count);
        cortex_m4_print("\n");
    }
    sample_count = 0;
}

/* ---- raw port_switch ping-pong, no kernel ---- */
static port_context_t ctx_main, ctx_pong;
static uint64_t pong_stack[64];
static volatile uint32_t switch_at;

static void pong(void *arg) {
    (void)arg;
    for (;;) {
        uint32_t t = now();
        sample("port_switch", t - switch_at);
        switch_at = now();
        port_switch(&ctx_pong, &ctx_main);
    }
}

static void raw_switch(void) {
    port_irq_disable();
    port_context_init(&ctx_pong, pong_stack, sizeof pong_stack, pong, NULL);
    for (unsigned i = 0; i < 20; i++) {
        switch_at = now();
        port_switch(&ctx_main, &ctx_pong);
        uint32_t t = now();
        if (i > 0) sample("port_switch", t - switch_at);
        port_irq_disable(); /* the first entry to pong enabled interrupts */
    }
    port_irq_enable();
}

/* ---- Sys_Yield between two threads ---- */
static volatile uint32_t yield_at;
static volatile unsigned yields;

static void yielder(void *arg) {
    (void)arg;
    for (;;) {
        uint32_t t = now();
        if (yields++ > 2 && yields < SAMPLES + 3) sample("yield", t - yield_at);
        yield_at = now();
        Sys_Yield();
    }
}

static void stop_after(uint32_t ms) {
    Sys_Sleep(ms);
    Sys_Stop_Kernel();
}

static void control_5(void *arg) {
    (void)arg;
    stop_after(5);
}

/* ---- two spinners preempted by the tick ----
 * The tick's hook works out when SysTick raised it (SysTick counts down
 * at the core clock, 168 MHz of virtual time: a count is 125/21 ns); the
 * spinners read only RAM until they find they were switched to, so their
 * first read of the counter is fresh. */
#define SYST_RVR (*(volatile uint32_t *)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018u)
static volatile uint32_t tick_raised_at;
static volatile uintptr_t running_spinner;
static volatile unsigned preemptions;

static void note_tick(void) {
    uint32_t t = now();
    tick_raised_at = t - (SYST_RVR - SYST_CVR) * 125u / 21u;
}

static void spinner(void *arg) {
    for (;;) {
        if (running_spinner == (uintptr_t)arg) continue;
        uint32_t t = now();
        if (running_spinner != 0 && preemptions++ < SAMPLES) sample("tick_switch", t - tick_raised_at);
        running_spinner = (uintptr_t)arg;
    }
}

static void control_1100(void *arg) {
    (void)arg;
    stop_after(1100);
}

/* ---- an interrupt's event: to a handler, to a woken thread ---- */
static volatile uint32_t raised_at;

void EXTI0_IRQHandler(void) {
    cortex_m4_isr_enter();
    Sys_Send_Event(EV, NULL, 0);
    cortex_m4_isr_exit();
}

static void raise_interrupt(void) {
    raised_at = now();
    NVIC_STIR = EXTI0_IRQ;
}

static bool timing_handler(sys_pid pid, sys_event_id e, const sys_event_data *d) {
    (void)pid;
    (void)e;
    (void)d;
    uint32_t t = now();
    sample("irq_to_handler", t - raised_at);
    return true;
}

static void raiser(void *arg) {
    (void)arg;
    for (unsigned i = 0; i < SAMPLES; i++) {
        raise_interrupt();
        Sys_Sleep(1);
    }
    Sys_Stop_Kernel();
}

static void woken(void *arg) {
    (void)arg;
    for (;;) {
        Sys_Wait_for_Event(EV, NULL, 0, NULL);
        uint32_t t = now();
        sample("irq_to_thread", t - raised_at);
    }
}

/* ---- sends from a thread, each run by a handler ---- */
static bool counting_handler(sys_pid pid, sys_event_id e, const sys_event_data *d) {
    (void)pid;
    (void)e;
    (void)d;
    return true;
}

static void sender(void *arg) {
    (void)arg;
    int16_t v = 1;
    uint32_t t0 = now();
    for (unsigned i = 0; i < SAMPLES; i++) Sys_Send_Event(EV, &v, sizeof v);
    sample("send_to_handler_x100", now() - t0);
    Sys_Stop_Kernel();
}

static void start(sys_process_fn fn, uintptr_t arg, uint8_t priority) {
    Sys_Start_Process_Ex(fn, (void *)arg, 512, priority, NULL);
}

static void run(void) {
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    print_samples();
}

int main(void) {
    TIM2_PSC = 0; /* one count a nanosecond: an instruction */
    TIM2_CR1 = 1;
    TIM2_ARR = 0xFFFFFFFFu;
    cortex_m4_irq_enable(EXTI0_IRQ, CORTEX_M4_PRIORITY_DEVICE);

    raw_switch();
    print_samples();

    Sys_Init_Kernel();
    start(control_5, 0, 0);
    start(yielder, 1, 0);
    start(yielder, 2, 0);
    run();

    Sys_Init_Kernel();
    cortex_m4_tick_hook = note_tick;
    start(control_1100, 0, 0);
    start(spinner, 1, 0);
    start(spinner, 2, 0);
    run();
    cortex_m4_tick_hook = NULL;

    /* A spinning thread is interrupted; the handler runs at once. */
    Sys_Init_Kernel();
    Sys_Register_Event_Sized(EV, 2);
    Sys_Subscribe_to_Event(EV, SYS_PID_SYSTEM, timing_handler, NULL);
    start(raiser, 0, 0);
    run();

    /* A waiting thread of higher priority than the interrupted one. */
    Sys_Init_Kernel();
    Sys_Set_Scheduler(&sys_scheduler_priority);
    Sys_Register_Event_Sized(EV, 2);
    start(raiser, 0, 0);
    start(woken, 0, 9);
    run();

    Sys_Init_Kernel();
    Sys_Register_Event_Sized(EV, 2);
    Sys_Subscribe_to_Event(EV, SYS_PID_SYSTEM, counting_handler, NULL);
    start(sender, 0, 0);
    run();
    return 0;
}
