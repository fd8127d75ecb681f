// Round-robin time slicing, the priority scheduler, and replacing the
// scheduler at run time.
#include "kernel_fixture.hpp"

#include <set>

using Scheduler = KernelTest;

[[noreturn]] static void spin(std::atomic<long> &counter) {
    for (;;) counter++;
}

// Who runs after each of n ticks.
static std::vector<sys_pid> sample(int n) {
    std::vector<sys_pid> who;
    for (int i = 0; i < n; i++) {
        host_cpu_advance(1);
        sys_pid p = SYS_PID_NONE;
        host_cpu_interrupt([](void *out) { *static_cast<sys_pid *>(out) = Sys_Get_ProcessID(); }, &p);
        who.push_back(p);
    }
    return who;
}

TEST_F(Scheduler, RoundRobinGivesEachThreadTenMillisecondSlices) {
    std::atomic<long> ca{0}, cb{0};
    sys_pid a = 0, b = 0;
    boot([&] {
        a = spawn([&] { spin(ca); });
        b = spawn([&] { spin(cb); });
    });
    std::vector<sys_pid> who = sample(40);
    for (int tick = 1; tick <= 40; tick++) {
        sys_pid expected = ((tick / 10) % 2 == 0) ? a : b;
        EXPECT_EQ(expected, who[tick - 1]) << "after tick " << tick;
    }
    // The thread on the CPU really runs (no tick is delivered meanwhile).
    EXPECT_EQ(a, running());
    long before = ca;
    EXPECT_TRUE(eventually([&] { return ca > before; }));
    advance(OS_CFG_TIME_SLICE_MS);
    EXPECT_EQ(b, running());
    EXPECT_TRUE(eventually([&] { return cb > 0; }));
    power_off();
}

TEST_F(Scheduler, TimeSliceIsConfigurable) {
    std::atomic<long> c[3] = {};
    sys_pid p[3] = {};
    sys_status zero = SYS_OK;
    boot([&] {
        EXPECT_STATUS(SYS_OK, Sys_Set_TimeSlice(3));
        zero = Sys_Set_TimeSlice(0);
        for (int i = 0; i < 3; i++) p[i] = spawn([&c, i] { spin(c[i]); });
    });
    std::vector<sys_pid> who = sample(18);
    for (int tick = 1; tick <= 18; tick++)
        EXPECT_EQ(p[(tick / 3) % 3], who[tick - 1]) << "after tick " << tick;
    EXPECT_STATUS(SYS_E_INVALID, zero);
    power_off();
}

TEST_F(Scheduler, SliceIsRenewedWhenNobodyElseIsReady) {
    std::atomic<long> c{0};
    sys_pid a = 0;
    boot([&] { a = spawn([&] { spin(c); }); });
    for (sys_pid p : sample(35)) EXPECT_EQ(a, p);
    power_off();
}

TEST_F(Scheduler, PriorityRunsTheHighestFirstAndRoundRobinAmongEquals) {
    std::atomic<long> low{0}, high1{0}, high2{0};
    sys_pid h1 = 0, h2 = 0;
    boot([&] {
        EXPECT_STATUS(SYS_OK, Sys_Set_Scheduler(&sys_scheduler_priority));
        spawn([&] { spin(low); }, 1);
        h1 = spawn([&] { spin(high1); }, 5);
        h2 = spawn([&] { spin(high2); }, 5);
    });
    std::vector<sys_pid> who = sample(40);
    for (int tick = 1; tick <= 40; tick++)
        EXPECT_EQ(((tick / 10) % 2 == 0) ? h1 : h2, who[tick - 1]) << "after tick " << tick;
    EXPECT_EQ(0, low.load()) << "a lower priority never runs while a higher one is ready";
    power_off();
}

TEST_F(Scheduler, WokenHigherPriorityThreadPreemptsAtOnce) {
    std::atomic<long> low{0};
    std::atomic<int> high_runs{0};
    sys_pid l = 0;
    boot([&] {
        Sys_Set_Scheduler(&sys_scheduler_priority);
        Sys_Register_Event(EV_A);
        spawn(
            [&] {
                for (;;) {
                    Sys_Wait_for_Event(EV_A, nullptr, 0, nullptr);
                    high_runs++;
                }
            },
            9);
        l = spawn([&] { spin(low); }, 1);
    });
    advance(1);
    // The high thread blocks on its own (no tick needed); on a loaded
    // machine that may come a little after advance() returns.
    ASSERT_TRUE(eventually([&] { return running() == l; })) << "the spinner runs";
    irq([] { Sys_Send_Event(EV_A, nullptr, 0); });
    // No tick is delivered from here on: under round robin it could not run.
    EXPECT_TRUE(eventually([&] { return high_runs == 1; })) << "preempted at once";
    EXPECT_TRUE(eventually([&] { return running() == l; })) << "and gave the CPU back";
    power_off();
}

TEST_F(Scheduler, WokenThreadWaitsForTheSliceUnderRoundRobin) {
    std::atomic<long> spinner{0};
    std::atomic<int> woken_runs{0};
    sys_pid s = 0;
    boot([&] {
        Sys_Register_Event(EV_A);
        spawn([&] {
            Sys_Wait_for_Event(EV_A, nullptr, 0, nullptr);
            woken_runs++;
        });
        s = spawn([&] { spin(spinner); });
    });
    advance(1);
    // The waiter blocks and the spinner runs (no tick needed); on a loaded
    // machine that may come after advance() returns, and an event sent
    // before the waiter waits would be missed.
    ASSERT_TRUE(eventually([&] { return running() == s; })) << "the spinner runs";
    irq([] { Sys_Send_Event(EV_A, nullptr, 0); });
    EXPECT_EQ(0, woken_runs.load());
    EXPECT_EQ(s, running());
    EXPECT_EQ(0, woken_runs.load()) << "still the spinner's slice";
    advance(OS_CFG_TIME_SLICE_MS);
    EXPECT_TRUE(eventually([&] { return woken_runs == 1; })) << "it ran when the slice ended";
    power_off();
}

TEST_F(Scheduler, ReplacedAtRunTime) {
    std::atomic<long> c[3] = {};
    sys_pid p[3] = {};
    boot([&] {
        for (int i = 0; i < 3; i++) p[i] = spawn([&c, i] { spin(c[i]); }, (uint8_t)(i + 1));
    });
    auto who_runs_each_slice = [&](int slices) {
        std::set<sys_pid> seen;
        for (int i = 0; i < slices; i++) {
            advance(OS_CFG_TIME_SLICE_MS);
            seen.insert(running());
        }
        return seen;
    };
    EXPECT_EQ((std::set<sys_pid>{p[0], p[1], p[2]}), who_runs_each_slice(3)) << "round robin";
    const sys_scheduler *before = nullptr;
    irq([&] {
        before = Sys_Get_Scheduler();
        Sys_Set_Scheduler(&sys_scheduler_priority);
    });
    EXPECT_EQ(&sys_scheduler_round_robin, before);
    EXPECT_EQ(p[2], running()) << "the highest priority takes over at once";
    EXPECT_EQ((std::set<sys_pid>{p[2]}), who_runs_each_slice(6)) << "priority";
    irq([] { Sys_Set_Scheduler(&sys_scheduler_round_robin); });
    EXPECT_EQ((std::set<sys_pid>{p[0], p[1], p[2]}), who_runs_each_slice(3)) << "round robin again";
    power_off();
}

// The ready list keeps its last thread for round robin's queueing: when
// that thread leaves (killed while ready), the next one queued goes after
// the one before it, and every thread still gets its turn.
TEST_F(Scheduler, AThreadQueuedAfterTheLastReadyOneWasKilledStillGetsItsTurn) {
    std::atomic<long> c[4] = {};
    sys_pid p[4] = {};
    boot([&] {
        for (int i = 0; i < 3; i++) p[i] = spawn([&c, i] { spin(c[i]); });
    });
    host_cpu_advance(1); /* p[0] runs; p[1] and p[2] (the last) are ready */
    ASSERT_EQ(p[0], running());
    irq([&] { EXPECT_STATUS(SYS_OK, Sys_Kill_Process(p[2])); });
    irq([&] { p[3] = spawn([&c] { spin(c[3]); }); });
    const sys_pid turns[3] = {p[0], p[1], p[3]};
    std::vector<sys_pid> who = sample(60); /* after ticks 2 to 61 */
    for (int tick = 2; tick <= 61; tick++)
        EXPECT_EQ(turns[(tick / 10) % 3], who[tick - 2]) << "after tick " << tick;
    power_off();
}

// A policy written by an application: last in, first out.
static void insert_at_head(sys_tcb **head, sys_tcb *t) {
    *Sys_Tcb_Next(t) = *head;
    *head = t;
}
static bool never(const sys_tcb *, const sys_tcb *) { return false; }
static const sys_scheduler lifo = {"lifo", insert_at_head, never};

TEST_F(Scheduler, ApplicationsCanSupplyTheirOwnPolicy) {
    boot([&] {
        EXPECT_STATUS(SYS_OK, Sys_Set_Scheduler(&lifo));
        spawn([] { note("first"); });
        spawn([] { note("second"); });
        spawn([] { note("third"); });
    });
    settle();
    EXPECT_EQ("third second first", joined());
}

TEST_F(Scheduler, IncompletePoliciesAreRejected) {
    static const sys_scheduler broken = {"broken", nullptr, never};
    sys_status null_policy = SYS_OK, broken_policy = SYS_OK;
    const sys_scheduler *after = nullptr;
    boot([&] {
        null_policy = Sys_Set_Scheduler(nullptr);
        broken_policy = Sys_Set_Scheduler(&broken);
        after = Sys_Get_Scheduler();
    });
    settle();
    EXPECT_STATUS(SYS_E_INVALID, null_policy);
    EXPECT_STATUS(SYS_E_INVALID, broken_policy);
    EXPECT_EQ(&sys_scheduler_round_robin, after);
}

TEST_F(Scheduler, RaisingAPriorityPreemptsTheRunningThread) {
    std::atomic<long> a{0}, b{0};
    sys_pid pa = 0, pb = 0;
    boot([&] {
        Sys_Set_Scheduler(&sys_scheduler_priority);
        pa = spawn([&] { spin(a); }, 2);
        pb = spawn([&] { spin(b); }, 1);
    });
    advance(1);
    EXPECT_EQ(pa, running());
    irq([&] { EXPECT_STATUS(SYS_OK, Sys_Set_Priority(pb, 3)); });
    EXPECT_EQ(pb, running());
    power_off();
}

// The end of an interrupt decides again only if something the decision
// reads changed (os.reconsider): a priority the interrupt lowers is such a
// change, even with no thread made ready.
TEST_F(Scheduler, LoweringTheRunningThreadsPriorityInAnInterruptSwitchesAtItsEnd) {
    std::atomic<long> a{0}, b{0};
    sys_pid pa = 0, pb = 0;
    boot([&] {
        Sys_Set_Scheduler(&sys_scheduler_priority);
        pa = spawn([&] { spin(a); }, 2);
        pb = spawn([&] { spin(b); }, 1);
    });
    advance(1);
    EXPECT_EQ(pa, running());
    irq([&] { EXPECT_STATUS(SYS_OK, Sys_Set_Priority(pa, 0)); });
    EXPECT_EQ(pb, running()) << "no tick came: the interrupt's end switched";
    power_off();
}
