/* The kernel's behaviour on a robot's CPU, as firmware: the same source
 * runs on the Kilobot's ATmega328P under openswarm-sim (avr.kernel_suite)
 * and on the e-puck2's Cortex-M4 under QEMU (qemu.kernel_suite).
 *
 * Each test boots a fresh kernel: setup() runs between Sys_Init_Kernel and
 * Sys_Start_Kernel and starts a control thread that exercises the kernel,
 * checks the outcome and stops the kernel. Time is the port's real 1 ms
 * tick; other interrupts come from a timer of the target (test_target.h). */
#include "openswarm/kernel.h"
#include "openswarm/port.h"
#include "test_target.h"

#include <string.h>

#define EV_A SYS_EVENT_FIRST_FREE
#define EV_B (SYS_EVENT_FIRST_FREE + 1)
#define CONTROL_STACK 160

static uint16_t passed, failed;

#define CHECK(cond) check((cond), __LINE__)
static void check(bool ok, uint16_t line) {
    if (ok) {
        passed++;
        return;
    }
    failed++;
    target_puts(TEXT("  FAIL at kernel_suite.c:"));
    target_put_uint(line);
    target_putc('\n');
}

/* Equality with both values in the failure message. */
#define CHECK_EQ(expected, actual) check_eq((uint32_t)(expected), (uint32_t)(actual), __LINE__)
static void check_eq(uint32_t expected, uint32_t actual, uint16_t line) {
    check(expected == actual, line);
    if (expected != actual) {
        target_puts(TEXT("    expected "));
        target_put_uint(expected);
        target_puts(TEXT(", got "));
        target_put_uint(actual);
        target_putc('\n');
    }
}

static char log_buf[16];
static uint8_t log_len;
static void note(char c) {
    if (log_len < sizeof log_buf - 1) log_buf[log_len++] = c;
    log_buf[log_len] = '\0';
}

static void start_control(sys_process_fn body) {
    sys_pid pid;
    Sys_Start_Process_Ex(body, NULL, CONTROL_STACK, 0, &pid);
}

static void finish(void) { Sys_Stop_Kernel(); }

static void interrupt_in(uint16_t us, int16_t value) { target_interrupt_in(us, value); }

void target_interrupt(int16_t value) { Sys_Send_IntEvent(EV_A, value); }

/* ---- threads and the scheduler ---- */

static void yielder(void *arg) {
    for (uint8_t i = 0; i < 3; i++) {
        note(*(const char *)arg);
        Sys_Yield();
    }
}

static void yield_control(void *arg) {
    (void)arg;
    Sys_Sleep(5);
    CHECK(strcmp(log_buf, "ababab") == 0);
    finish();
}

static const char letter_a = 'a', letter_b = 'b';
static void yield_setup(void) {
    start_control(yield_control);
    Sys_Start_Process_Ex(yielder, (void *)&letter_a, 0, 0, NULL);
    Sys_Start_Process_Ex(yielder, (void *)&letter_b, 0, 0, NULL);
}

static volatile uint32_t spins[2];
static sys_pid spinner_pid[2];
static void spinner(void *arg) {
    volatile uint32_t *counter = arg;
    for (;;) (*counter)++;
}

static void preempt_control(void *arg) {
    (void)arg;
    uint32_t t0 = Sys_Get_SystemTime();
    uint32_t switches0 = Sys_Get_SwitchCount();
    Sys_Sleep(50);
    /* Woken at 50 ms, it queues behind the spinners: at most two slices. */
    uint32_t slept = Sys_Get_SystemTime() - t0;
    CHECK(slept >= 50 && slept <= 50 + 2 * OS_CFG_TIME_SLICE_MS);
    CHECK(spins[0] > 0 && spins[1] > 0);
    CHECK(Sys_Get_SwitchCount() - switches0 >= 4); /* 10 ms slices */
    sys_process_state st;
    CHECK(Sys_Get_ProcessState(spinner_pid[0], &st) == SYS_OK && st != SYS_PROCESS_BLOCKED);
    finish();
}

static void preempt_setup(void) {
    spins[0] = spins[1] = 0;
    start_control(preempt_control);
    Sys_Start_Process_Ex(spinner, (void *)&spins[0], 0, 0, &spinner_pid[0]);
    Sys_Start_Process_Ex(spinner, (void *)&spins[1], 0, 0, &spinner_pid[1]);
}

static void returner(void) { note('r'); }

static void reap_control(void *arg) {
    (void)arg;
    for (uint8_t i = 0; i < 12; i++) { /* twice as many threads as slots */
        CHECK(Sys_Start_Process(returner) != SYS_PID_NONE);
        Sys_Yield();
    }
    CHECK_EQ(12, log_len);
    sys_stats s;
    Sys_Get_Stats(&s);
    CHECK(s.process_pool_full == 0 && s.stack_pool_full == 0);
    finish();
}

static void reap_setup(void) { start_control(reap_control); }

static volatile uint32_t high_ran_at, isr_sent_at;
static void high_waiter(void *arg) {
    (void)arg;
    Sys_Wait_for_Event(EV_A, NULL, 0, NULL);
    high_ran_at = Sys_Get_SystemTime();
}

static void priority_control(void *arg) {
    (void)arg;
    Sys_Sleep(3); /* the spinner holds the CPU, the waiter is blocked */
    isr_sent_at = Sys_Get_SystemTime();
    interrupt_in(50, 1);
    Sys_Sleep(20);
    CHECK(high_ran_at != 0);
    CHECK_EQ(isr_sent_at, high_ran_at); /* preempted the spinner at once */
    finish();
}

static void priority_setup(void) {
    high_ran_at = 0;
    Sys_Set_Scheduler(&sys_scheduler_priority);
    Sys_Register_Event(EV_A);
    start_control(priority_control);
    CHECK_EQ(SYS_E_INVALID, Sys_Set_Priority(SYS_PID_SYSTEM, 5)); /* never queued */
    Sys_Start_Process_Ex(high_waiter, NULL, 0, 9, NULL);
    Sys_Start_Process_Ex(spinner, (void *)&spins[0], 0, 0, NULL);
}

/* ---- time ---- */

/* Most ticks count the time and the slice and look no further (the quiet
 * ticks, system_time.c); here every tick interrupts one of two spinning
 * threads. A 300 ms sleep crosses the clock's lowest byte and ends on
 * time; a 5 ms sleep started then, while the next deadline (the far
 * sleeper's) is 700 ms away, ends on time too; the slices turn meanwhile.
 * The control thread outranks the spinners: it reads the time as it wakes. */
static void far_sleeper(void *arg) {
    (void)arg;
    Sys_Sleep(1000);
}

static void time_control(void *arg) {
    (void)arg;
    uint32_t t0 = Sys_Get_SystemTime();
    uint32_t switches0 = Sys_Get_SwitchCount();
    Sys_Sleep(300);
    CHECK_EQ(t0 + 300, Sys_Get_SystemTime());
    Sys_Sleep(5);
    CHECK_EQ(t0 + 305, Sys_Get_SystemTime());
    CHECK(Sys_Get_SwitchCount() - switches0 >= 300 / OS_CFG_TIME_SLICE_MS);
    CHECK(spins[0] > 0 && spins[1] > 0);
    finish();
}

static void time_setup(void) {
    spins[0] = spins[1] = 0;
    Sys_Set_Scheduler(&sys_scheduler_priority);
    Sys_Start_Process_Ex(time_control, NULL, CONTROL_STACK, 2, NULL);
    Sys_Start_Process_Ex(far_sleeper, NULL, 0, 1, NULL);
    Sys_Start_Process_Ex(spinner, (void *)&spins[0], 0, 0, NULL);
    Sys_Start_Process_Ex(spinner, (void *)&spins[1], 0, 0, NULL);
}

/* ---- events and waiting ---- */

static bool record_handler(sys_pid pid, sys_event_id e, const sys_event_data *d) {
    (void)pid;
    (void)e;
    int16_t v;
    memcpy(&v, d->value, sizeof v);
    note((char)('0' + v));
    return true;
}

static void events_control(void *arg) {
    (void)arg;
    note('<');
    Sys_Send_IntEvent(EV_A, 3);
    note('>');
    CHECK(strcmp(log_buf, "<3>") == 0); /* handlers ran before Send returned */
    int16_t kept = 0;
    CHECK(Sys_Get_EventData(EV_A, &kept, sizeof kept, NULL) == SYS_OK && kept == 3);

    int16_t got = 0;
    interrupt_in(100, 7); /* from an interrupt */
    CHECK(Sys_Wait_for_Event_Timeout(EV_A, 5, &got, sizeof got, NULL) == SYS_OK);
    CHECK(got == 7);
    CHECK(strcmp(log_buf, "<3>7") == 0);
    CHECK(Sys_Send_Event(EV_B, &got, 2) == SYS_E_NOT_REGISTERED);
    CHECK(Sys_Send_Event(EV_A, log_buf, 3) == SYS_E_TOO_BIG);
    finish();
}

static void events_setup(void) {
    Sys_Register_Event(EV_A);
    Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, record_handler, NULL);
    start_control(events_control);
}

static volatile int16_t waiter_got[3];
static void waiter(void *arg) {
    int16_t v = 0;
    Sys_Wait_for_Event(EV_A, &v, sizeof v, NULL);
    *(volatile int16_t *)arg = v;
}

static bool is_even(const sys_event_data *d) {
    int16_t v;
    memcpy(&v, d->value, sizeof v);
    return (v & 1) == 0;
}

static void wait_control(void *arg) {
    (void)arg;
    Sys_Sleep(1); /* the waiters block */
    Sys_Send_IntEvent(EV_A, 21);
    Sys_Yield(); /* woken, the waiters run in turn */
    CHECK(waiter_got[0] == 21 && waiter_got[1] == 21 && waiter_got[2] == 21);

    uint32_t t0 = Sys_Get_SystemTime();
    CHECK(Sys_Wait_for_Condition_Timeout(EV_A, is_even, 20, NULL, 0, NULL) == SYS_E_TIMEOUT);
    uint32_t waited = Sys_Get_SystemTime() - t0;
    CHECK(waited == 20 || waited == 21); /* a tick may fall between t0 and the wait */
    interrupt_in(200, 5); /* odd: does not wake a condition wait */
    CHECK(Sys_Wait_for_Condition_Timeout(EV_A, is_even, 3, NULL, 0, NULL) == SYS_E_TIMEOUT);
    interrupt_in(200, 8);
    int16_t v = 0;
    CHECK(Sys_Wait_for_Condition_Timeout(EV_A, is_even, 3, &v, sizeof v, NULL) == SYS_OK);
    CHECK(v == 8);
    finish();
}

static void wait_setup(void) {
    Sys_Register_Event(EV_A);
    start_control(wait_control);
    for (uint8_t i = 0; i < 3; i++) {
        waiter_got[i] = 0;
        Sys_Start_Process_Ex(waiter, (void *)&waiter_got[i], 0, 0, NULL);
    }
}

/* Handlers with a context: each binding's handler gets its own pointer
 * back, its condition filters, an interrupt's event reaches it, returning
 * false or unsubscribing ends only that binding. */
typedef struct tally {
    char mark;
    uint8_t calls;
    int16_t sum;
} tally;
static tally first, second;

static bool add_to_tally(void *context, sys_pid pid, const sys_event_data *d) {
    (void)pid;
    tally *t = context;
    int16_t v;
    memcpy(&v, d->value, sizeof v);
    t->calls++;
    t->sum = (int16_t)(t->sum + v);
    note(t->mark);
    return t->calls < 3; /* the third call ends the subscription */
}

static const sys_event_binding to_first = {add_to_tally, &first, NULL};
static const sys_event_binding to_second = {add_to_tally, &second, is_even};

static void context_control(void *arg) {
    (void)arg;
    CHECK(Sys_Subscribe_with_Context(EV_A, SYS_PID_SYSTEM, &to_first) == SYS_OK);
    CHECK(Sys_Subscribe_with_Context(EV_A, SYS_PID_SYSTEM, &to_second) == SYS_OK);
    CHECK(Sys_Subscribe_with_Context(EV_A, SYS_PID_SYSTEM, &to_first) == SYS_E_EXISTS);
    CHECK(Sys_Subscribe_with_Context(EV_A, SYS_PID_SYSTEM, NULL) == SYS_E_INVALID);
    Sys_Send_IntEvent(EV_A, 4); /* both: even */
    Sys_Send_IntEvent(EV_A, 5); /* first only */
    CHECK(strcmp(log_buf, "fsf") == 0);
    CHECK_EQ(9, first.sum);
    CHECK_EQ(4, second.sum);
    interrupt_in(100, 6);
    Sys_Sleep(2); /* from an interrupt: first's third call ends it */
    CHECK(strcmp(log_buf, "fsffs") == 0);
    CHECK_EQ(3, first.calls);
    CHECK(Sys_Unsubscribe_with_Context(EV_A, SYS_PID_SYSTEM, &to_first) == SYS_E_NOT_FOUND);
    CHECK(Sys_Unsubscribe_with_Context(EV_A, SYS_PID_SYSTEM, &to_second) == SYS_OK);
    Sys_Send_IntEvent(EV_A, 8);
    CHECK(strcmp(log_buf, "fsffs") == 0); /* nobody left */
    CHECK_EQ(10, second.sum);
    finish();
}

static void context_setup(void) {
    first = (tally){'f', 0, 0};
    second = (tally){'s', 0, 0};
    Sys_Register_Event(EV_A);
    start_control(context_control);
}

/* A handler that unsubscribes itself must not make the next one be skipped. */
static bool self_removing(sys_pid pid, sys_event_id e, const sys_event_data *d) {
    (void)d;
    note('s');
    Sys_Unsubscribe_from_Event(e, pid, self_removing);
    return true;
}
static bool next_handler(sys_pid pid, sys_event_id e, const sys_event_data *d) {
    (void)pid;
    (void)e;
    (void)d;
    note('n');
    return true;
}
static bool dead_handler(sys_pid pid, sys_event_id e, const sys_event_data *d) {
    (void)pid;
    (void)e;
    (void)d;
    note('X');
    return true;
}
static void sleeper(void *arg) {
    (void)arg;
    Sys_Sleep(60000);
}

static void regression_control(void *arg) {
    (void)arg;
    sys_pid victim;
    Sys_Start_Process_Ex(sleeper, NULL, 0, 0, &victim);
    Sys_Yield();
    CHECK(Sys_Subscribe_to_Event(EV_A, victim, dead_handler, NULL) == SYS_OK);
    CHECK(Sys_Kill_Process(victim) == SYS_OK);
    CHECK(Sys_Get_ProcessState(victim, NULL) == SYS_E_INVALID);
    Sys_Send_Event(EV_A, NULL, 0);
    Sys_Send_Event(EV_A, NULL, 0);
    CHECK(strcmp(log_buf, "snn") == 0);
    CHECK(Sys_Unregister_Event(EV_A) == SYS_OK);
    CHECK(Sys_Unregister_Event(EV_A) == SYS_E_NOT_REGISTERED);
    finish();
}

static void regression_setup(void) {
    Sys_Register_Event_Sized(EV_A, 0);
    Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, self_removing, NULL);
    Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, next_handler, NULL);
    start_control(regression_control);
}

/* ---- critical sections, pools, faults ---- */

static void critical_control(void *arg) {
    (void)arg;
    Sys_Start_CriticalSection();
    uint32_t t0 = Sys_Get_SystemTime();
    while (Sys_Get_SystemTime() - t0 < 30) {
    } /* three slices, time goes on */
    CHECK(spins[0] == 0);
    CHECK(Sys_End_CriticalSection() == SYS_OK);
    CHECK(Sys_End_CriticalSection() == SYS_E_INVALID);
    Sys_Sleep(1);
    CHECK(spins[0] > 0);
    finish();
}

static void critical_setup(void) {
    spins[0] = 0;
    start_control(critical_control);
    Sys_Start_Process_Ex(spinner, (void *)&spins[0], 0, 0, NULL);
}

static void pools_control(void *arg) {
    (void)arg;
    uint8_t started = 0;
    sys_pid pid;
    /* A stack size near the 16-bit limit is too big, not wrapped round. */
    CHECK(Sys_Start_Process_Ex(sleeper, NULL, 65535u - 8u, 0, &pid) == SYS_E_POOL_FULL);
    while (Sys_Start_Process_Ex(sleeper, NULL, 16, 0, &pid) == SYS_OK) started++;
    CHECK_EQ(OS_CFG_MAX_THREADS - 2, started); /* minus the system and control threads */
    sys_stats s;
    Sys_Get_Stats(&s);
    CHECK(s.process_pool_full == 1);
    CHECK(s.stack_pool_full == 1);

    uint8_t accepted = 0;
    Sys_Start_CriticalSection();
    for (uint8_t i = 0; i < 20; i++)
        if (Sys_Send_IntEvent(EV_A, i) == SYS_OK) accepted++;
    Sys_End_CriticalSection();
    CHECK_EQ(OS_CFG_EVENT_QUEUE_BYTES / 4 + 1, accepted); /* the first held, the rest in the ring */
    Sys_Get_Stats(&s);
    CHECK_EQ(20u - accepted, s.event_queue_full);
    CHECK(log_len == accepted); /* every accepted one was handled */
    finish();
}

static void pools_setup(void) {
    Sys_Register_Event(EV_A);
    Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, record_handler, NULL);
    start_control(pools_control);
}

static sys_pid expected_fault_pid = SYS_PID_NONE; /* faults the test provokes */
static volatile uint8_t fault_seen;
static volatile sys_pid fault_pid;
static void on_fault(sys_fault f, sys_pid pid) {
    fault_seen = (uint8_t)f;
    fault_pid = pid;
}

static void overflower(void *arg) {
    (void)arg;
    volatile uint8_t big[64 + PORT_STACK_EXTRA + 32]; /* more than its whole stack */
    for (uint16_t i = 0; i < sizeof big; i++) big[i] = (uint8_t)i;
    Sys_Yield();
    note('!'); /* never: the guard check kills it */
}

static void fault_control(void *arg) {
    (void)arg;
    sys_pid spacer, victim;
    /* The spacer's stack lies just below the victim's; once it is reaped the
     * overflow lands in free pool memory, not in a live thread. */
    Sys_Start_Process_Ex(sleeper, NULL, 64, 0, &spacer);
    Sys_Start_Process_Ex(overflower, NULL, 64, 0, &victim);
    expected_fault_pid = victim;
    Sys_Kill_Process(spacer);
    Sys_Sleep(5);
    CHECK(fault_seen == SYS_FAULT_STACK_OVERFLOW);
    CHECK(fault_pid == victim);
    CHECK(Sys_Get_ProcessState(victim, NULL) == SYS_E_INVALID);
    CHECK(log_len == 0);
    sys_stats s;
    Sys_Get_Stats(&s);
    CHECK(s.stack_overflows == 1);
    finish();
}

static void fault_setup(void) {
    fault_seen = 0;
    Sys_Set_FaultHook(on_fault);
    start_control(fault_control);
}

/* A thread that overflows and then spins makes no decision of its own:
 * the tick that ends its slice checks its guard. */
static void spinning_overflower(void *arg) {
    (void)arg;
    volatile uint8_t big[64 + PORT_STACK_EXTRA + 32]; /* more than its whole stack */
    for (uint16_t i = 0; i < sizeof big; i++) big[i] = (uint8_t)i;
    for (;;) {
    }
}

static void spin_fault_control(void *arg) {
    (void)arg;
    sys_pid spacer, victim;
    Sys_Start_Process_Ex(sleeper, NULL, 64, 0, &spacer); /* as in fault_control */
    Sys_Start_Process_Ex(spinning_overflower, NULL, 64, 0, &victim);
    expected_fault_pid = victim;
    Sys_Kill_Process(spacer);
    Sys_Sleep(OS_CFG_TIME_SLICE_MS + 5); /* the victim spins alone for a slice */
    CHECK(fault_seen == SYS_FAULT_STACK_OVERFLOW);
    CHECK(fault_pid == victim);
    CHECK(Sys_Get_ProcessState(victim, NULL) == SYS_E_INVALID);
    finish();
}

static void spin_fault_setup(void) {
    fault_seen = 0;
    Sys_Set_FaultHook(on_fault);
    start_control(spin_fault_control);
}

/* ---- the runner ---- */

/* An unexpected fault (a control thread outgrowing its stack) fails the
 * test and ends it, instead of leaving it to hang. */
static bool report_fault(sys_pid pid, sys_event_id e, const sys_event_data *d) {
    (void)pid;
    (void)e;
    sys_fault_info info;
    memcpy(&info, d->value, sizeof info);
    if (info.pid == expected_fault_pid) return true;
    failed++;
    target_puts(TEXT("  FAULT "));
    target_put_uint(info.fault);
    target_puts(TEXT(" in pid "));
    target_put_uint(info.pid);
    target_putc('\n');
    finish();
    return true;
}

typedef struct test_case {
    const char *name; /* in flash */
    void (*setup)(void);
} test_case;

static void run(const char *name, void (*setup)(void)) {
    uint16_t failed_before = failed;
    expected_fault_pid = SYS_PID_NONE;
    log_len = 0;
    log_buf[0] = '\0';
    Sys_Init_Kernel();
    Sys_Subscribe_to_Event(SYS_EVENT_FAULT, SYS_PID_SYSTEM, report_fault, NULL);
    setup();
    Sys_Start_Kernel();
    Sys_Run_SystemThread();
    target_puts(failed == failed_before ? TEXT("ok   ") : TEXT("FAIL "));
    target_puts(name);
    target_putc('\n');
}

#define RUN(name) run(TEXT(#name), name##_setup)

int main(void) {
    target_init();
    RUN(yield);
    RUN(preempt);
    RUN(reap);
    RUN(priority);
    RUN(time);
    RUN(events);
    RUN(wait);
    RUN(context);
    RUN(regression);
    RUN(critical);
    RUN(pools);
    RUN(fault);
    RUN(spin_fault);
    target_put_uint(passed);
    target_puts(TEXT(" passed, "));
    target_put_uint(failed);
    target_puts(TEXT(" failed\n"));
    target_exit(failed == 0 ? 0 : 1);
}
