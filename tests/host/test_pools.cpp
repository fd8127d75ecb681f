// Every static pool and queue: a full one makes the call fail visibly and
// increments its counter; nothing is lost silently.
#include "kernel_fixture.hpp"

using Pools = KernelTest;

static void sleeper(void *) { Sys_Sleep(1000000); }

TEST_F(Pools, ThreadSlotsRunOut) {
    int started = 0;
    sys_status last = SYS_OK;
    sys_pid none = 0;
    boot([&] {
        sys_pid pid;
        while ((last = Sys_Start_Process_Ex(sleeper, nullptr, 32, 0, &pid)) == SYS_OK) started++;
        none = Sys_Start_Process([] {});
    });
    settle();
    EXPECT_EQ(OS_CFG_MAX_THREADS - 1, started);
    EXPECT_STATUS(SYS_E_POOL_FULL, last);
    EXPECT_EQ(SYS_PID_NONE, none);
    EXPECT_EQ(2u, stats().process_pool_full);
}

TEST_F(Pools, StackPoolRunsOutAndFreedStacksAreReused) {
    int started = 0;
    sys_status last = SYS_OK;
    sys_pid first = 0;
    boot([&] {
        sys_pid pid;
        // Large stacks exhaust the pool before the thread slots.
        while ((last = Sys_Start_Process_Ex(sleeper, nullptr, 60000, 0, &pid)) == SYS_OK) {
            if (started++ == 0) first = pid;
        }
    });
    settle();
    EXPECT_STATUS(SYS_E_POOL_FULL, last);
    EXPECT_LT(started, OS_CFG_MAX_THREADS - 1) << "the stack pool, not the slots, ran out";
    EXPECT_EQ(1u, stats().stack_pool_full);
    sys_status again = SYS_OK;
    irq([&] { Sys_Kill_Process(first); });
    settle();
    irq([&] {
        sys_pid pid;
        again = Sys_Start_Process_Ex(sleeper, nullptr, 60000, 0, &pid);
    });
    EXPECT_STATUS(SYS_OK, again) << "the reaped thread's stack is free again";
}

// A handler that ends a thread, then another that starts one, from a single
// interrupt while a thread runs: the ended thread is reaped before the second
// handler, so its slot is there to reuse (kilolib swaps its activity threads
// so when the overhead controller asks, with every slot in use).
static sys_pid victim;
static sys_status restart;
TEST_F(Pools, AThreadEndedByAHandlerIsReapedBeforeTheNextHandlerRuns) {
    restart = SYS_E_INVALID;
    boot([&] {
        spawn([] {
            for (;;) {
            }
        });
        sys_pid pid;
        victim = SYS_PID_NONE;
        while (Sys_Start_Process_Ex(sleeper, nullptr, 32, 0, &pid) == SYS_OK)
            if (victim == SYS_PID_NONE) victim = pid;
        Sys_Register_Event(EV_A);
        Sys_Register_Event(EV_B);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM,
                               [](sys_pid, sys_event_id, const sys_event_data *) {
                                   Sys_Kill_Process(victim);
                                   return true;
                               },
                               nullptr);
        Sys_Subscribe_to_Event(EV_B, SYS_PID_SYSTEM,
                               [](sys_pid, sys_event_id, const sys_event_data *) {
                                   sys_pid again;
                                   restart = Sys_Start_Process_Ex(sleeper, nullptr, 32, 0, &again);
                                   return true;
                               },
                               nullptr);
    });
    irq([] {}); // the set-up has run; the spinner runs now
    irq([] {
        Sys_Send_Event(EV_A, nullptr, 0);
        Sys_Send_Event(EV_B, nullptr, 0);
    });
    ASSERT_TRUE(eventually([&] { return restart != SYS_E_INVALID; }));
    EXPECT_STATUS(SYS_OK, restart);
    power_off();
}

TEST_F(Pools, EventDataArenaRunsOutAndUnregisteredBlocksAreReused) {
    sys_status first = SYS_E_INVALID, second = SYS_OK, reuse = SYS_E_INVALID;
    boot([&] {
        first = Sys_Register_Event_Sized(EV_A, 200);
        second = Sys_Register_Event_Sized(EV_B, 200);
        Sys_Unregister_Event(EV_A);
        reuse = Sys_Register_Event_Sized(EV_C, 150);
    });
    settle();
    EXPECT_STATUS(SYS_OK, first);
    EXPECT_STATUS(SYS_E_POOL_FULL, second);
    EXPECT_STATUS(SYS_OK, reuse);
    EXPECT_EQ(1u, stats().event_data_full);
}

TEST_F(Pools, SubscriptionsRunOut) {
    int made = 0;
    sys_status last = SYS_OK;
    boot([&] {
        // One handler, many events: each (event, thread, handler) is a subscription.
        for (sys_event_id e = EV_A; e < EV_A + OS_CFG_MAX_SUBSCRIPTIONS + 1; e++) Sys_Register_Event(e);
        for (sys_event_id e = EV_A; e < EV_A + OS_CFG_MAX_SUBSCRIPTIONS + 1; e++) {
            last = Sys_Subscribe_to_Event(
                e, SYS_PID_SYSTEM, [](sys_pid, sys_event_id, const sys_event_data *) { return true; },
                nullptr);
            if (last != SYS_OK) break;
            made++;
        }
    });
    settle();
    EXPECT_EQ(OS_CFG_MAX_SUBSCRIPTIONS, made);
    EXPECT_STATUS(SYS_E_POOL_FULL, last);
    EXPECT_EQ(1u, stats().subscription_pool_full);
}

// A handler subscribed to an event nobody registered never runs: counted,
// so that the end of a run can say so (issue 31).
TEST_F(Pools, SubscriptionToAnUnregisteredEventIsCounted) {
    sys_status st = SYS_OK;
    boot([&] {
        st = Sys_Subscribe_to_Event(
            EV_A, SYS_PID_SYSTEM, [](sys_pid, sys_event_id, const sys_event_data *) { return true; },
            nullptr);
    });
    settle();
    EXPECT_STATUS(SYS_E_NOT_REGISTERED, st);
    EXPECT_EQ(1u, stats().subscriptions_refused);
}

TEST_F(Pools, FullEventQueueRefusesSendsAndLosesNoneItAccepted) {
    static std::atomic<int> handled{0};
    handled = 0;
    std::atomic<int> accepted{0}, refused{0};
    boot([&] {
        Sys_Register_Event(EV_A);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM,
                               [](sys_pid, sys_event_id, const sys_event_data *) {
                                   handled++;
                                   return true;
                               },
                               nullptr);
        spawn([&] {
            Sys_Start_CriticalSection(); // nothing is dispatched meanwhile
            for (int i = 0; i < 100; i++) {
                if (Sys_Send_IntEvent(EV_A, (int16_t)i) == SYS_OK)
                    accepted++;
                else
                    refused++;
            }
            Sys_End_CriticalSection();
        });
    });
    settle();
    EXPECT_EQ(OS_CFG_EVENT_QUEUE_BYTES / 4 + 1, accepted.load())
        << "the first held in its event's kept data, then 2 B header + 2 B data each";
    EXPECT_EQ(100 - accepted, refused.load());
    EXPECT_EQ(accepted.load(), handled.load()) << "every accepted occurrence was handled";
    sys_stats s = stats();
    EXPECT_EQ((unsigned)refused.load(), s.event_queue_full);
    EXPECT_EQ(OS_CFG_EVENT_QUEUE_BYTES, s.event_queue_peak);
}

TEST_F(Pools, FullEventQueueFromAnInterrupt) {
    sys_status last = SYS_OK;
    int accepted = 0;
    boot([&] { Sys_Register_Event_Sized(EV_A, 10); });
    irq([&] {
        uint8_t ten[10] = {};
        while ((last = Sys_Send_Event(EV_A, ten, sizeof ten)) == SYS_OK) accepted++;
    });
    settle();
    EXPECT_STATUS(SYS_E_QUEUE_FULL, last);
    EXPECT_EQ(OS_CFG_EVENT_QUEUE_BYTES / 12 + 1, accepted) << "the first held, the rest in the ring";
    EXPECT_EQ(1u, stats().event_queue_full);
}

// 70000 refusals: the counter stops at 65535; a wrapped one would read
// 4464, and after exactly 65536 losses it would read 0.
TEST_F(Pools, CountersStopAtTheirTopInsteadOfWrapping) {
    long refused = 0;
    boot([&] { Sys_Register_Event_Sized(EV_A, 10); });
    irq([&] {
        uint8_t ten[10] = {};
        while (Sys_Send_Event(EV_A, ten, sizeof ten) == SYS_OK) {
        }
        for (long i = 1; i < 70000; i++)
            if (Sys_Send_Event(EV_A, ten, sizeof ten) == SYS_E_QUEUE_FULL) refused++;
    });
    settle();
    EXPECT_EQ(69999, refused);
    EXPECT_EQ(65535u, stats().event_queue_full);
}

TEST_F(Pools, EventTableIsBoundedById) {
    sys_status last = SYS_E_INVALID;
    boot([&] { last = Sys_Register_Event_Sized(OS_CFG_MAX_EVENTS, 0); });
    settle();
    EXPECT_STATUS(SYS_E_INVALID, last);
}
