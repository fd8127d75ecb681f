// One test per failure mode of the original OpenSwarm implementation
// (see shared/design.md, "Known defects").
#include "kernel_fixture.hpp"

#include <cstring>

using Regression = KernelTest;

// Original: a second thread waiting on an event overwrote the first
// waiter, which then blocked forever.
TEST_F(Regression, SecondWaiterDoesNotOverwriteTheFirst) {
    std::atomic<int> woke{0};
    sys_pid first = 0, second = 0;
    boot([&] {
        Sys_Register_Event(EV_A);
        first = spawn([&] {
            Sys_Wait_for_Event(EV_A, nullptr, 0, nullptr);
            woke |= 1;
        });
        second = spawn([&] {
            Sys_Wait_for_Event(EV_A, nullptr, 0, nullptr);
            woke |= 2;
        });
    });
    settle();
    irq([] { Sys_Send_Event(EV_A, nullptr, 0); });
    settle();
    EXPECT_EQ(3, woke.load());
    EXPECT_FALSE(alive(first));
    EXPECT_FALSE(alive(second));
}

// Original: blocking could switch into another blocked thread.
TEST_F(Regression, BlockingNeverSwitchesIntoABlockedThread) {
    boot([&] {
        Sys_Register_Event(EV_A);
        Sys_Register_Event(EV_B);
        Sys_Register_Event(EV_C);
        spawn([] {
            Sys_Wait_for_Event(EV_A, nullptr, 0, nullptr);
            note("a");
        });
        spawn([] {
            Sys_Wait_for_Event(EV_B, nullptr, 0, nullptr);
            note("b");
        });
        spawn([] {
            Sys_Wait_for_Event(EV_C, nullptr, 0, nullptr);
            note("c");
        });
    });
    settle();
    irq([] { Sys_Send_Event(EV_C, nullptr, 0); });
    settle();
    irq([] { Sys_Send_Event(EV_A, nullptr, 0); });
    settle();
    EXPECT_EQ("c a", joined()) << "b must still be blocked";
}

// Original: a wait by the only ready thread returned stale data at once.
TEST_F(Regression, WaitByTheOnlyThreadBlocksInsteadOfReturningStaleData) {
    std::atomic<int> got{0};
    sys_pid t = 0;
    boot([&] {
        Sys_Register_Event(EV_A);
        Sys_Send_IntEvent(EV_A, 1); // stale by the time anybody waits
        t = spawn([&] {
            int16_t v = 0;
            Sys_Wait_for_Event(EV_A, &v, sizeof v, nullptr);
            got = v;
        });
    });
    settle();
    EXPECT_EQ(SYS_PROCESS_BLOCKED, state_of(t));
    EXPECT_EQ(0, got.load());
    irq([] { Sys_Send_IntEvent(EV_A, 2); });
    settle();
    EXPECT_EQ(2, got.load());
}

// Original: killing a blocked thread left a subscription pointing at
// freed memory.
TEST_F(Regression, KillingABlockedThreadRemovesItsSubscriptions) {
    sys_pid t = 0;
    boot([&] {
        Sys_Register_Event(EV_A);
        for (sys_event_id e = EV_B; e < EV_B + OS_CFG_MAX_SUBSCRIPTIONS; e++)
            Sys_Register_Event_Sized(e, 0);
        t = spawn([] { Sys_Sleep(1000000); });
        Sys_Subscribe_to_Event(EV_A, t,
                               [](sys_pid, sys_event_id, const sys_event_data *) {
                                   note("dead thread's handler ran");
                                   return true;
                               },
                               nullptr);
    });
    settle();
    irq([&] { Sys_Kill_Process(t); });
    settle();
    irq([] { Sys_Send_Event(EV_A, nullptr, 0); });
    settle();
    EXPECT_EQ("", joined());
    // Its subscription slot is free again: the pool holds a full set.
    int made = 0;
    irq([&] {
        for (sys_event_id e = 0; e < OS_CFG_MAX_EVENTS && made < OS_CFG_MAX_SUBSCRIPTIONS; e++)
            if (Sys_Subscribe_to_Event(e, SYS_PID_SYSTEM,
                                       [](sys_pid, sys_event_id, const sys_event_data *) { return true; },
                                       nullptr) == SYS_OK)
                made++;
    });
    EXPECT_EQ(OS_CFG_MAX_SUBSCRIPTIONS, made);
}

// Original: a handler that unsubscribed itself during dispatch made later
// handlers be skipped.
static bool self_removing(sys_pid pid, sys_event_id e, const sys_event_data *) {
    note("self");
    Sys_Unsubscribe_from_Event(e, pid, self_removing);
    return true;
}
static bool returning_false(sys_pid, sys_event_id, const sys_event_data *) {
    note("once");
    return false;
}
static bool later(sys_pid, sys_event_id, const sys_event_data *) {
    note("later");
    return true;
}
static bool last(sys_pid, sys_event_id, const sys_event_data *) {
    note("last");
    return true;
}
static bool removes_last(sys_pid pid, sys_event_id e, const sys_event_data *) {
    note("remover");
    Sys_Unsubscribe_from_Event(e, pid, last);
    return true;
}

TEST_F(Regression, HandlerUnsubscribingItselfDoesNotSkipLaterHandlers) {
    boot([&] {
        Sys_Register_Event(EV_A);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, self_removing, nullptr);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, returning_false, nullptr);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, later, nullptr);
    });
    irq([] { Sys_Send_Event(EV_A, nullptr, 0); });
    irq([] { Sys_Send_Event(EV_A, nullptr, 0); });
    settle();
    EXPECT_EQ("self once later later", joined());
}

TEST_F(Regression, HandlerUnsubscribingALaterOneTakesEffectAtOnce) {
    boot([&] {
        Sys_Register_Event(EV_A);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, removes_last, nullptr);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, later, nullptr);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, last, nullptr);
    });
    irq([] { Sys_Send_Event(EV_A, nullptr, 0); });
    settle();
    EXPECT_EQ("remover later", joined());
}

// Original: unregistering an event freed it twice.
TEST_F(Regression, UnregisteringTwiceIsAnErrorAndRegistrationCyclesDoNotLeak) {
    sys_status twice = SYS_OK;
    int cycles = 0;
    boot([&] {
        Sys_Register_Event_Sized(EV_A, 32);
        Sys_Unregister_Event(EV_A);
        twice = Sys_Unregister_Event(EV_A);
        for (int i = 0; i < 1000; i++) {
            if (Sys_Register_Event_Sized((sys_event_id)(EV_A + i % 3), 32) != SYS_OK) break;
            if (Sys_Unregister_Event((sys_event_id)(EV_A + i % 3)) != SYS_OK) break;
            cycles++;
        }
    });
    settle();
    EXPECT_STATUS(SYS_E_NOT_REGISTERED, twice);
    EXPECT_EQ(1000, cycles);
    EXPECT_EQ(0u, stats().event_data_full);
}

// Original: every send allocated from the heap with interrupts off. Ours
// copies into a static queue: sustained traffic never fails or grows.
TEST_F(Regression, SustainedSendingNeedsNoMemoryBeyondTheQueue) {
    static std::atomic<long> sum{0};
    sum = 0;
    std::atomic<int> failures{0};
    boot([&] {
        Sys_Register_Event(EV_A);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM,
                               [](sys_pid, sys_event_id, const sys_event_data *d) {
                                   int16_t v;
                                   std::memcpy(&v, d->value, sizeof v);
                                   sum += v;
                                   return true;
                               },
                               nullptr);
        spawn([&] {
            for (int i = 0; i < 20000; i++)
                if (Sys_Send_IntEvent(EV_A, 1) != SYS_OK) failures++;
        });
    });
    settle();
    EXPECT_EQ(0, failures.load());
    EXPECT_EQ(20000, sum.load());
    EXPECT_LE(stats().event_queue_peak, 4) << "one occurrence in flight at a time";
}

// Original: the context switch relied on the compiler's -O0 frame layout.
// Here: deep call chains with live locals survive thousands of preemptions.
static uint32_t checksum(int depth, uint32_t seed) {
    volatile uint32_t local[8];
    for (int i = 0; i < 8; i++) local[i] = seed * 2654435761u + (uint32_t)i;
    uint32_t below = depth > 0 ? checksum(depth - 1, local[3]) : 0;
    uint32_t s = below;
    for (int i = 0; i < 8; i++) s = s * 31u + local[i];
    return s;
}

TEST_F(Regression, ContextsSurvivePreemptionAtAnyPoint) {
    constexpr int kThreads = 3;
    const uint32_t expected = checksum(20, 7);
    std::atomic<int> rounds[kThreads] = {};
    std::atomic<int> wrong{0};
    boot([&] {
        for (int t = 0; t < kThreads; t++) {
            spawn(
                [&, t] {
                    for (;;) {
                        if (checksum(20, 7) != expected) wrong++;
                        rounds[t]++;
                    }
                },
                0, 2048);
        }
    });
    for (int i = 0; i < 300; i++) advance(1);
    for (auto &r : rounds) EXPECT_GT(r.load(), 0);
    EXPECT_EQ(0, wrong.load());
    uint32_t switches = 0;
    irq([&] { switches = Sys_Get_SwitchCount(); });
    EXPECT_GE(switches, 300u / OS_CFG_TIME_SLICE_MS - 1);
    power_off();
}

// Original: threads could not return.
TEST_F(Regression, ThreadsMayReturn) {
    sys_pid t = 0;
    boot([&] { t = spawn([] { note("returned"); }); });
    settle();
    EXPECT_EQ("returned", joined());
    EXPECT_FALSE(alive(t));
}

// Original: critical sections leaked (a thread ending inside one froze the
// scheduler).
TEST_F(Regression, CriticalSectionDoesNotOutliveItsThread) {
    std::atomic<long> a{0}, b{0};
    boot([&] {
        spawn([] { Sys_Start_CriticalSection(); });
        spawn([&] {
            for (;;) a++;
        });
        spawn([&] {
            for (;;) b++;
        });
    });
    advance(3 * OS_CFG_TIME_SLICE_MS);
    EXPECT_TRUE(eventually([&] { return a > 0 && b > 0; }));
    power_off();
}

// Original: the right wheel's getter returned the left wheel. Two output
// devices sharing one post-processor keep their values apart.
static int16_t applied[2];
static uint8_t store_speed(sys_device *, const void *in, uint8_t size, void *out, uint8_t) {
    std::memcpy(out, in, size);
    return size;
}
static void write_wheel(sys_device *dev, const void *raw, uint8_t) {
    std::memcpy(&applied[*static_cast<int *>(dev->params)], raw, sizeof(int16_t));
}
static int left_index = 0, right_index = 1;

TEST_F(Regression, EachWheelGetsItsOwnCommand) {
    static sys_device left, right;
    left = sys_device{"left", SYS_DEVICE_OUTPUT, EV_A, 0, store_speed, nullptr, write_wheel, &left_index, 0};
    right = sys_device{"right", SYS_DEVICE_OUTPUT, EV_B, 0, store_speed, nullptr, write_wheel, &right_index, 0};
    applied[0] = applied[1] = 0;
    boot([&] {
        EXPECT_STATUS(SYS_OK, Sys_Register_Device(&left));
        EXPECT_STATUS(SYS_OK, Sys_Register_Device(&right));
        spawn([] {
            Sys_Send_IntEvent(EV_A, 11);
            Sys_Send_IntEvent(EV_B, -22);
        });
    });
    settle();
    EXPECT_EQ(11, applied[0]);
    EXPECT_EQ(-22, applied[1]);
}
