/* Cycle-exact kernel costs on the ATmega328P, measured in the shapes apps
 * use them: several call sites, 2 and 4 user threads, with and without a
 * thread spinning. The firmware writes markers to GPIOR2; openswarm-sim
 * --marks prints the exact cycle of every change (and --watch-irq every
 * interrupt raised), and bench/avr_bench.py turns them into per-occurrence
 * samples. Each phase is one run of the kernel, ended by a control thread
 * that sleeps (blocked: never in the way) and stops the kernel. Markers:
 *   10/11      raw port_switch ping-pong (no kernel)
 *   20-21      Sys_Yield, 2 threads (thread i writes 20+i, then yields)
 *   22-25      Sys_Yield, 4 threads
 *   30-33      2 spinning threads (thread i alternates 30+2i, 31+2i):
 *              the tick (vector 14) switches, or returns to the same one
 *   34-41      4 spinning threads
 *   44         interrupt (Timer2 compare, vector 7) to an event handler,
 *              a thread spinning (42/43)
 *   45         the same, no thread running (the system thread idles)
 *   50         interrupt to a woken thread, no other thread running
 *   51         interrupt to a woken thread of higher priority than a
 *              thread spinning (52/53)
 *   60/61/62   a thread sends (60), its handler runs (61), the thread goes
 *              on (62)
 *   70/71      1 spinning thread: every tick returns to it, every 10th at
 *              the end of its slice (nobody else ready: a fresh one) */
#include "openswarm/kernel.h"
#include "openswarm/kilobot_sim.h"
#include "openswarm/port.h"

#define MARK(v) (GPIOR2 = (v))
#define EV (SYS_EVENT_FIRST_FREE)
#define INTERRUPTS 40 /* per interrupt phase */
#define SENDS 100

/* ---- raw switch ---- */
static port_context_t ctx_a, ctx_b;
static uint8_t stack_b[96];

static void pong(void *arg) {
    (void)arg;
    for (;;) {
        MARK(11);
        port_switch(&ctx_b, &ctx_a);
    }
}

static void raw_switch(void) {
    cli();
    port_context_init(&ctx_b, stack_b, sizeof stack_b, pong, NULL);
    for (uint8_t i = 0; i < 20; i++) {
        MARK(10);
        port_switch(&ctx_a, &ctx_b);
        cli(); /* the first entry to pong enabled interrupts */
    }
}

/* ---- phase plumbing ---- */
static void start(sys_process_fn fn, uint8_t arg, uint8_t priority) {
    if (Sys_Start_Process_Ex(fn, (void *)(uint16_t)arg, 0, priority, NULL) != SYS_OK) MARK(0xEE);
}

static void run_phase(void) {
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
}

static void stop_after(void *arg) {
    Sys_Sleep((uint16_t)arg);
    Sys_Stop_Kernel();
}

/* ---- Sys_Yield: two functions call it, so link-time optimisation cannot
 * fold it into one caller ---- */
static void yield_here(void *arg) {
    uint8_t mark = (uint8_t)(uint16_t)arg;
    for (;;) {
        MARK(mark);
        Sys_Yield();
    }
}

static void yield_there(void *arg) {
    uint8_t mark = (uint8_t)(uint16_t)arg;
    for (;;) {
        MARK(mark);
        if (Sys_Yield() != SYS_OK) MARK(0xFF); /* a caller that looks at the result */
    }
}

static void yield_phase(uint8_t threads, uint8_t first_mark) {
    Sys_Init_Kernel();
    start(stop_after, 20, 0);
    for (uint8_t i = 0; i < threads; i++)
        start(i & 1 ? yield_there : yield_here, (uint8_t)(first_mark + i), 0);
    run_phase();
}

/* ---- the tick: preemption and the tick that returns ---- */
static void spinner(void *arg) {
    uint8_t mark = (uint8_t)(uint16_t)arg;
    for (;;) {
        MARK(mark);
        MARK(mark + 1);
    }
}

static void tick_phase(uint8_t threads, uint8_t first_mark) {
    Sys_Init_Kernel();
    start(stop_after, 100, 0);
    for (uint8_t i = 0; i < threads; i++) start(spinner, (uint8_t)(first_mark + 2 * i), 0);
    run_phase();
}

/* ---- interrupts: Timer2 compare sends an event ---- */
static void timer2_in_us(uint8_t us) {
    TCCR2A = _BV(WGM21);
    TCNT2 = 0;
    OCR2A = us;
    TIFR2 = _BV(OCF2A);
    TIMSK2 = _BV(OCIE2A);
    TCCR2B = _BV(CS21); /* 1 us per count */
}

ISR(TIMER2_COMPA_vect) {
    TCCR2B = 0;
    TIMSK2 = 0;
    os_isr_enter();
    Sys_Send_Event(EV, NULL, 0);
    os_isr_exit();
}

/* Arms the interrupt every 2 ms (half-way between two ticks), then stops. */
static void interrupt_control(void *arg) {
    (void)arg;
    for (uint8_t i = 0; i < INTERRUPTS; i++) {
        Sys_Sleep(2);
        timer2_in_us(100);
    }
    Sys_Sleep(3);
    Sys_Stop_Kernel();
}

static uint8_t handler_mark;
static bool marking_handler(sys_pid pid, sys_event_id e, const sys_event_data *d) {
    (void)pid;
    (void)e;
    (void)d;
    MARK(handler_mark);
    MARK(0);
    return true;
}

static void handler_phase(bool spinning, uint8_t mark) {
    Sys_Init_Kernel();
    handler_mark = mark;
    Sys_Register_Event_Sized(EV, 2);
    Sys_Subscribe_to_Event(EV, SYS_PID_SYSTEM, marking_handler, NULL);
    start(interrupt_control, 0, 0);
    if (spinning) start(spinner, 42, 0);
    run_phase();
}

static void woken(void *arg) {
    uint8_t mark = (uint8_t)(uint16_t)arg;
    for (;;) {
        Sys_Wait_for_Event(EV, NULL, 0, NULL);
        MARK(mark);
        MARK(0);
    }
}

/* The woken thread and the control thread outrank the spinner, which
 * runs whenever both wait (the priority scheduler). */
static void wake_phase(bool spinning, uint8_t mark) {
    Sys_Init_Kernel();
    Sys_Register_Event_Sized(EV, 2);
    if (spinning) Sys_Set_Scheduler(&sys_scheduler_priority);
    start(interrupt_control, 0, 2);
    start(woken, mark, 1);
    if (spinning) start(spinner, 52, 0);
    run_phase();
}

/* ---- a thread's send, dispatched at once to a handler ---- */
static bool round_trip_handler(sys_pid pid, sys_event_id e, const sys_event_data *d) {
    (void)pid;
    (void)e;
    (void)d;
    MARK(61);
    return true;
}

static void sender(void *arg) {
    (void)arg;
    int16_t v = 1;
    for (uint8_t i = 0; i < SENDS; i++) {
        MARK(60);
        Sys_Send_Event(EV, &v, sizeof v);
        MARK(62);
    }
    Sys_Stop_Kernel();
}

static void send_phase(void) {
    Sys_Init_Kernel();
    Sys_Register_Event_Sized(EV, 2);
    Sys_Subscribe_to_Event(EV, SYS_PID_SYSTEM, round_trip_handler, NULL);
    start(sender, 0, 0);
    run_phase();
}

int main(void) {
    raw_switch();
    yield_phase(2, 20);
    yield_phase(4, 22);
    tick_phase(2, 30);
    tick_phase(4, 34);
    tick_phase(1, 70);
    handler_phase(true, 44);
    handler_phase(false, 45);
    wake_phase(false, 50);
    wake_phase(true, 51);
    send_phase();
    sim_exit(0);
}
