/* Tickless idle on the Cortex-M4 keeps the kernel's time exact
 * (qemu.tickless_time): built twice, with the periodic tick and with
 * tickless idle, the image prints the same lines, and
 * check_tickless_time.py compares them.
 *   - a thread sleeps 1, 2, 3 ... 1000 ms in turn, then until 10000 ms,
 *     then waits 2.5 s for an event that never comes;
 *   - interrupts in the middle of those sleeps (TIM3, at 1280.5, 3333.5
 *     and 5000.5 ms of the tick grid) read the time and wake a thread at
 *     once, which then sleeps 10 ms on the grid the wake put back;
 *   - two threads that never block keep the tick: the time slice switches
 *     between them;
 *   - the tick interrupts taken (the tick hook's calls), and where the
 *     grid lies in QEMU's virtual time at the end: the first differs
 *     between the builds, the second must agree within a few counts.
 *
 * QEMU's timers count at 1 GHz of virtual time and, with -icount, a tick
 * of SysTick takes 1 ms of it. TIM3 updates every 250 us
 * from boot (its count cleared first: QEMU interrupts without end otherwise) and calls the kernel only at the first update past a poke's
 * time; TIM5 runs free as the virtual clock, in 100 ns counts. */
#include "busy_threads.h"
#include "openswarm/cortex_m4.h"
#include "openswarm/kernel.h"

#define TIM_REG(base, offset) (*(volatile uint32_t *)((base) + (offset)))
#define TIM3_BASE 0x40000400u
#define TIM5_BASE 0x40000C00u
#define TIM_CR1 0x00u
#define TIM_DIER 0x0Cu
#define TIM_SR 0x10u
#define TIM_CNT 0x24u
#define TIM_PSC 0x28u
#define TIM_ARR 0x2Cu
#define TIM3_IRQ 29
#define VIRTUAL_PER_TICK 10000u /* 100 ns counts of TIM5 in a tick */

#define EV_POKE SYS_EVENT_FIRST_FREE
#define EV_NEVER (SYS_EVENT_FIRST_FREE + 1)

static const uint32_t poke_ms[] = {1280, 3333, 5000};
#define POKES (sizeof poke_ms / sizeof poke_ms[0])

static void say(const char *text, uint32_t value) {
    cortex_m4_print(text);
    cortex_m4_print_uint(value);
    cortex_m4_print("\n");
}

static uint32_t virtual_counts(void) { return TIM_REG(TIM5_BASE, TIM_CNT); }

/* Started at boot: QEMU's timers keep time only then. */
static void start_timers(void) {
    TIM_REG(TIM5_BASE, TIM_PSC) = 99; /* 100 ns a count */
    TIM_REG(TIM5_BASE, TIM_CR1) = 1;
    TIM_REG(TIM5_BASE, TIM_ARR) = 0xFFFFFFFFu; /* QEMU schedules the counter when ARR is written */
    TIM_REG(TIM3_BASE, TIM_PSC) = 999;          /* 1 us a count */
    TIM_REG(TIM3_BASE, TIM_SR) = 0;
    TIM_REG(TIM3_BASE, TIM_DIER) = 1;
    TIM_REG(TIM3_BASE, TIM_CR1) = 1;
    TIM_REG(TIM3_BASE, TIM_CNT) = 0;
    TIM_REG(TIM3_BASE, TIM_ARR) = 250;
    cortex_m4_irq_enable(TIM3_IRQ, CORTEX_M4_PRIORITY_DEVICE);
}

/* The tick grid, from the first tick interrupt: ms grid_ms began at
 * virtual count grid_at. */
static volatile uint32_t grid_ms, grid_at, tick_interrupts;
static volatile uint32_t last_tick_ms, last_tick_at; /* the latest tick interrupt's */
static volatile bool grid_known;

static void count_tick(void) {
    uint32_t now = Sys_Get_SystemTime();
    last_tick_at = virtual_counts();
    last_tick_ms = now;
    tick_interrupts++;
    if (!grid_known) {
        grid_at = virtual_counts();
        grid_ms = now;
        grid_known = true;
    }
    cortex_m4_tick_hook_ms = now + 0x40000000u; /* never limits a sleep */
}

static volatile unsigned pokes_done;

void TIM3_IRQHandler(void) {
    TIM_REG(TIM3_BASE, TIM_SR) = 0;
    if (!grid_known || pokes_done == POKES) return;
    uint32_t due = grid_at + ((poke_ms[pokes_done] - grid_ms) * 2u + 1u) * (VIRTUAL_PER_TICK / 2u);
    if ((int32_t)(virtual_counts() - due) < 0) return;
    pokes_done++;
    cortex_m4_isr_enter();
    uint32_t now = Sys_Get_SystemTime();
    Sys_Send_Event(EV_POKE, &now, sizeof now);
    cortex_m4_isr_exit();
}

static void waiter(void *arg) {
    (void)arg;
    for (unsigned i = 0; i < POKES; i++) {
        uint32_t sent_at = 0;
        Sys_Wait_for_Event(EV_POKE, &sent_at, sizeof sent_at, NULL);
        say("the interrupt read ms ", sent_at);
        say("its waiter woke at ms ", Sys_Get_SystemTime());
        Sys_Sleep(10);
        say("and slept 10 ms to ms ", Sys_Get_SystemTime());
    }
}

static void busy_threads(void) {
    busy_threads_result busy = busy_threads_run();
    say("busy threads: a 200 ms sleep woke at ms ", busy.woke_at_ms);
    say("switches meanwhile ", busy.switches);
    say("both spun ", (uint32_t)busy.both_spun);
}

static void sleeper(void *arg) {
    (void)arg;
    static const uint32_t naps[] = {1, 2, 3, 5, 7, 10, 50, 99, 100, 101, 150, 250, 1000};
    for (unsigned i = 0; i < sizeof naps / sizeof naps[0]; i++) {
        Sys_Sleep(naps[i]);
        say("slept ", naps[i]);
        say("  to ms ", Sys_Get_SystemTime());
    }
    uint32_t wake = 0;
    Sys_Sleep_Until(&wake, 10000);
    say("a sleep until 10 s woke at ms ", Sys_Get_SystemTime());
    sys_status st = Sys_Wait_for_Event_Timeout(EV_NEVER, 2500, NULL, 0, NULL);
    say("a 2.5 s timeout ended at ms ", Sys_Get_SystemTime());
    say("timed out ", (uint32_t)(st == SYS_E_TIMEOUT));
    busy_threads();
    /* Where the last tick came against where the first one's grid puts it. */
    int32_t drift = (int32_t)(last_tick_at - (grid_at + (last_tick_ms - grid_ms) * VIRTUAL_PER_TICK));
    cortex_m4_print(drift < 0 ? "the grid moved by -" : "the grid moved by ");
    say("", (uint32_t)(drift < 0 ? -drift : drift));
    say("tick interrupts ", tick_interrupts);
    board_halt(0);
}

int main(void) {
    start_timers();
    cortex_m4_tick_hook = count_tick;
    Sys_Init_Kernel();
    Sys_Register_Event_Sized(EV_POKE, sizeof(uint32_t));
    Sys_Register_Event_Sized(EV_NEVER, 0);
    Sys_Start_Process_Ex(waiter, NULL, 0, 0, NULL);
    Sys_Start_Process_Ex(sleeper, NULL, 0, 0, NULL);
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    return 0;
}
