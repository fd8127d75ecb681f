/* Cycle-exact kernel costs on the ATmega328P. The firmware writes markers
 * to GPIOR2; openswarm-sim --marks prints the exact cycle of every change,
 * and bench/avr_bench.py turns the pairs into costs. Marker values:
 *   10/11  raw port_switch ping-pong (no kernel)
 *   20/21  Sys_Yield between two threads
 *   30/31  two spinning threads, preempted by the tick (vector 14)
 *   40/41  a spinning thread, and the handler of an event an interrupt
 *          (Timer2 compare, vector 7) sends
 *   50     a thread woken by an event an interrupt sends
 *   60/61  start/end of 100 sends from a thread, each run by a handler */
#include "openswarm/kernel.h"
#include "openswarm/kilobot_sim.h"
#include "openswarm/port.h"

#define MARK(v) (GPIOR2 = (v))
#define EV (SYS_EVENT_FIRST_FREE)

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

/* ---- kernel phases ---- */
static void stop_after(uint16_t ms) {
    Sys_Sleep(ms);
    Sys_Stop_Kernel();
}

static void yielder(void *arg) {
    uint8_t mark = (uint8_t)(uint16_t)arg;
    for (;;) {
        MARK(mark);
        Sys_Yield();
    }
}

static void yield_control(void *arg) {
    (void)arg;
    stop_after(5);
}

static void spinner(void *arg) {
    uint8_t mark = (uint8_t)(uint16_t)arg;
    for (;;) MARK(mark);
}

static void spin_control(void *arg) {
    (void)arg;
    stop_after(100);
}

static volatile uint8_t interrupts_left;
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

static bool marking_handler(sys_pid pid, sys_event_id e, const sys_event_data *d) {
    (void)pid;
    (void)e;
    (void)d;
    MARK(41);
    return true;
}

static void interrupt_control(void *arg) {
    (void)arg;
    for (uint8_t i = 0; i < 8; i++) {
        Sys_Sleep(2);
        timer2_in_us(100);
    }
    stop_after(3);
}

static void woken(void *arg) {
    (void)arg;
    for (;;) {
        Sys_Wait_for_Event(EV, NULL, 0, NULL);
        MARK(50);
        MARK(0);
    }
}

static bool counting_handler(sys_pid pid, sys_event_id e, const sys_event_data *d) {
    (void)pid;
    (void)e;
    (void)d;
    return true;
}

static void throughput(void *arg) {
    (void)arg;
    int16_t v = 1;
    MARK(60);
    for (uint8_t i = 0; i < 100; i++) Sys_Send_Event(EV, &v, sizeof v);
    MARK(61);
    Sys_Stop_Kernel();
}

static void start(sys_process_fn fn, uint8_t arg) {
    Sys_Start_Process_Ex(fn, (void *)(uint16_t)arg, 0, 0, NULL);
}

int main(void) {
    raw_switch();

    Sys_Init_Kernel();
    start(yield_control, 0);
    start(yielder, 20);
    start(yielder, 21);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();

    Sys_Init_Kernel();
    start(spin_control, 0);
    start(spinner, 30);
    start(spinner, 31);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();

    Sys_Init_Kernel();
    Sys_Register_Event_Sized(EV, 2);
    Sys_Subscribe_to_Event(EV, SYS_PID_SYSTEM, marking_handler, NULL);
    start(interrupt_control, 0);
    start(spinner, 40);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();

    Sys_Init_Kernel();
    Sys_Register_Event_Sized(EV, 2);
    start(interrupt_control, 0);
    start(woken, 0);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();

    Sys_Init_Kernel();
    Sys_Register_Event_Sized(EV, 2);
    Sys_Subscribe_to_Event(EV, SYS_PID_SYSTEM, counting_handler, NULL);
    start(throughput, 0);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();

    sim_exit(0);
}
