// Blocking on events: plain, with a condition, with a timeout; many waiters.
#include "kernel_fixture.hpp"

#include <cstring>

using Wait = KernelTest;

static bool is_even(const sys_event_data *d) {
    int16_t v;
    std::memcpy(&v, d->value, sizeof v);
    return v % 2 == 0;
}

TEST_F(Wait, BlocksUntilTheEventAndReceivesACopyOfItsData) {
    std::atomic<int> got{0};
    std::atomic<int> size{0};
    sys_pid t = 0;
    boot([&] {
        Sys_Register_Event(EV_A);
        t = spawn([&] {
            int16_t v = 0;
            uint8_t n = 0;
            EXPECT_STATUS(SYS_OK, Sys_Wait_for_Event(EV_A, &v, sizeof v, &n));
            got = v;
            size = n;
        });
    });
    settle();
    EXPECT_EQ(SYS_PROCESS_BLOCKED, state_of(t));
    irq([] { Sys_Send_IntEvent(EV_A, -321); });
    settle();
    EXPECT_EQ(-321, got.load());
    EXPECT_EQ(2, size.load());
}

TEST_F(Wait, ConditionWaitWakesOnlyOnMatchingData) {
    std::atomic<int> got{0};
    sys_pid t = 0;
    boot([&] {
        Sys_Register_Event(EV_A);
        t = spawn([&] {
            int16_t v = 0;
            EXPECT_STATUS(SYS_OK, Sys_Wait_for_Condition(EV_A, is_even, &v, sizeof v, nullptr));
            got = v;
        });
    });
    irq([] { Sys_Send_IntEvent(EV_A, 3); });
    settle();
    EXPECT_EQ(SYS_PROCESS_BLOCKED, state_of(t));
    irq([] {
        Sys_Send_IntEvent(EV_A, 5);
        Sys_Send_IntEvent(EV_A, 8);
        Sys_Send_IntEvent(EV_A, 10);
    });
    settle();
    EXPECT_EQ(8, got.load());
}

TEST_F(Wait, EveryWaiterOnOneEventIsWokenWithItsOwnCopy) {
    constexpr int kWaiters = 6;
    std::atomic<int> got[kWaiters] = {};
    boot([&] {
        Sys_Register_Event(EV_A);
        for (int i = 0; i < kWaiters; i++) {
            spawn([&got, i] {
                int16_t v = 0;
                EXPECT_STATUS(SYS_OK, Sys_Wait_for_Event(EV_A, &v, sizeof v, nullptr));
                got[i] = v + i;
            });
        }
    });
    settle();
    irq([] { Sys_Send_IntEvent(EV_A, 100); });
    settle();
    for (int i = 0; i < kWaiters; i++) EXPECT_EQ(100 + i, got[i].load()) << "waiter " << i;
}

// The dispatch's scan ends at the last thread that waits for an event:
// sleepers and waiters for other events between them are passed over but
// not taken for the last, and the waiter in the last slot is still woken.
TEST_F(Wait, WaitersAmongSleepersAndOtherEventsAreAllFound) {
    std::atomic<int> woken_a{0}, woken_b{0}, slept{0};
    boot([&] {
        Sys_Register_Event(EV_A);
        Sys_Register_Event(EV_B);
        for (int i = 0; i < OS_CFG_MAX_THREADS - 1; i++) {
            switch (i % 3) {
            case 0: /* slots 1, 4, 7: wait for EV_A */
                spawn([&] { if (Sys_Wait_for_Event(EV_A, nullptr, 0, nullptr) == SYS_OK) woken_a++; });
                break;
            case 1: /* slots 2, 5, 8: asleep */
                spawn([&] { if (Sys_Sleep(1000) == SYS_OK) slept++; });
                break;
            default: /* slots 3, 6, 9 (the last): wait for EV_B */
                spawn([&] { if (Sys_Wait_for_Event(EV_B, nullptr, 0, nullptr) == SYS_OK) woken_b++; });
            }
        }
    });
    settle();
    irq([] { Sys_Send_Event(EV_A, nullptr, 0); });
    settle();
    EXPECT_EQ(3, woken_a.load());
    EXPECT_EQ(0, woken_b.load());
    irq([] { Sys_Send_Event(EV_B, nullptr, 0); });
    settle();
    EXPECT_EQ(3, woken_b.load()) << "the last slot's waiter among them";
    EXPECT_EQ(0, slept.load());
    advance(1000);
    settle();
    EXPECT_EQ(3, slept.load());
}

TEST_F(Wait, TimesOutAfterExactlyTheTimeout) {
    std::atomic<int> result{1};
    sys_pid t = 0;
    boot([&] {
        Sys_Register_Event(EV_A);
        t = spawn([&] { result = Sys_Wait_for_Event_Timeout(EV_A, 5, nullptr, 0, nullptr); });
    });
    settle();
    advance(4);
    settle();
    EXPECT_EQ(SYS_PROCESS_BLOCKED, state_of(t));
    advance(1);
    settle();
    EXPECT_STATUS(SYS_E_TIMEOUT, (sys_status)result.load());
}

TEST_F(Wait, EventBeforeTheTimeoutWins) {
    std::atomic<int> result{1}, value{0};
    boot([&] {
        Sys_Register_Event(EV_A);
        spawn([&] {
            int16_t v = 0;
            result = Sys_Wait_for_Event_Timeout(EV_A, 5, &v, sizeof v, nullptr);
            value = v;
        });
    });
    settle(); // blocked at time 0
    advance(4);
    irq([] { Sys_Send_IntEvent(EV_A, 9); });
    settle();
    advance(10);
    settle();
    EXPECT_STATUS(SYS_OK, (sys_status)result.load());
    EXPECT_EQ(9, value.load());
}

TEST_F(Wait, ConditionWaitWithTimeout) {
    std::atomic<int> first{1}, second{1}, value{0};
    boot([&] {
        Sys_Register_Event(EV_A);
        spawn([&] {
            int16_t v = 0;
            first = Sys_Wait_for_Condition_Timeout(EV_A, is_even, 3, &v, sizeof v, nullptr);
            second = Sys_Wait_for_Condition_Timeout(EV_A, is_even, 3, &v, sizeof v, nullptr);
            value = v;
        });
    });
    settle(); // blocked at time 0
    irq([] { Sys_Send_IntEvent(EV_A, 1); }); // does not satisfy the condition
    advance(3);
    settle();
    irq([] { Sys_Send_IntEvent(EV_A, 4); });
    settle();
    EXPECT_STATUS(SYS_E_TIMEOUT, (sys_status)first.load());
    EXPECT_STATUS(SYS_OK, (sys_status)second.load());
    EXPECT_EQ(4, value.load());
}

TEST_F(Wait, ZeroTimeoutReturnsAtOnce) {
    std::atomic<int> result{1};
    boot([&] {
        Sys_Register_Event(EV_A);
        spawn([&] { result = Sys_Wait_for_Event_Timeout(EV_A, 0, nullptr, 0, nullptr); });
    });
    settle();
    EXPECT_STATUS(SYS_E_TIMEOUT, (sys_status)result.load());
}

TEST_F(Wait, DataLargerThanTheBufferIsTruncatedAndSaysSo) {
    std::atomic<int> result{1}, size{0}, first_byte{0};
    boot([&] {
        Sys_Register_Event_Sized(EV_A, 6);
        spawn([&] {
            uint8_t two[2] = {0, 0};
            uint8_t n = 0;
            result = Sys_Wait_for_Event(EV_A, two, sizeof two, &n);
            size = n;
            first_byte = two[0];
        });
    });
    settle();
    irq([] {
        const uint8_t six[6] = {7, 8, 9, 10, 11, 12};
        Sys_Send_Event(EV_A, six, sizeof six);
    });
    settle();
    EXPECT_STATUS(SYS_E_TRUNCATED, (sys_status)result.load());
    EXPECT_EQ(6, size.load());
    EXPECT_EQ(7, first_byte.load());
}

TEST_F(Wait, UnregisteredEventsAndWrongContextsAreRefused) {
    sys_status unregistered = SYS_OK, in_handler = SYS_OK, in_isr = SYS_OK, no_cond = SYS_OK,
               range = SYS_OK;
    static sys_status handler_result;
    handler_result = SYS_OK;
    boot([&] {
        Sys_Register_Event(EV_B);
        Sys_Subscribe_to_Event(EV_B, SYS_PID_SYSTEM,
                               [](sys_pid, sys_event_id, const sys_event_data *) {
                                   handler_result = Sys_Wait_for_Event(EV_B, nullptr, 0, nullptr);
                                   return true;
                               },
                               nullptr);
        spawn([&] {
            unregistered = Sys_Wait_for_Event(EV_A, nullptr, 0, nullptr);
            no_cond = Sys_Wait_for_Condition(EV_B, nullptr, nullptr, 0, nullptr);
            range = Sys_Wait_for_Event(OS_CFG_MAX_EVENTS, nullptr, 0, nullptr);
        });
    });
    settle();
    irq([&] {
        in_isr = Sys_Wait_for_Event(EV_B, nullptr, 0, nullptr);
        Sys_Send_Event(EV_B, nullptr, 0);
    });
    settle();
    in_handler = handler_result;
    EXPECT_STATUS(SYS_E_NOT_REGISTERED, unregistered);
    EXPECT_STATUS(SYS_E_INVALID, no_cond);
    EXPECT_STATUS(SYS_E_INVALID, range);
    EXPECT_STATUS(SYS_E_CONTEXT, in_isr);
    EXPECT_STATUS(SYS_E_CONTEXT, in_handler);
}

TEST_F(Wait, UnregisteringTheEventWakesItsWaiters) {
    std::atomic<int> result{1};
    boot([&] {
        Sys_Register_Event(EV_A);
        spawn([&] { result = Sys_Wait_for_Event(EV_A, nullptr, 0, nullptr); });
        spawn([] {
            Sys_Yield(); // let the waiter block first
            Sys_Unregister_Event(EV_A);
        });
    });
    settle();
    EXPECT_STATUS(SYS_E_NOT_REGISTERED, (sys_status)result.load());
}

TEST_F(Wait, KillingAWaiterLeavesTheOthersWaiting) {
    std::atomic<int> survivor{0};
    sys_pid victim = 0;
    boot([&] {
        Sys_Register_Event(EV_A);
        victim = spawn([] {
            Sys_Wait_for_Event(EV_A, nullptr, 0, nullptr);
            note("victim woke");
        });
        spawn([&] {
            int16_t v = 0;
            Sys_Wait_for_Event(EV_A, &v, sizeof v, nullptr);
            survivor = v;
        });
    });
    settle();
    irq([&] { EXPECT_STATUS(SYS_OK, Sys_Kill_Process(victim)); });
    settle();
    EXPECT_FALSE(alive(victim));
    irq([] { Sys_Send_IntEvent(EV_A, 55); });
    settle();
    EXPECT_EQ(55, survivor.load());
    EXPECT_EQ("", joined());
}
