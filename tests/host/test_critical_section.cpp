// Critical sections postpone thread switches and event dispatch, nest,
// and cannot leak.
#include "kernel_fixture.hpp"

using CriticalSection = KernelTest;

TEST_F(CriticalSection, PostponesTheSwitchToItsEnd) {
    std::atomic<bool> release{false}, ended{false};
    std::atomic<long> other{0};
    sys_pid holder = 0, b = 0;
    boot([&] {
        holder = spawn([&] {
            Sys_Start_CriticalSection();
            while (!release) {
            }
            Sys_End_CriticalSection();
            ended = true;
            for (;;) {
            }
        });
        b = spawn([&] {
            for (;;) other++;
        });
    });
    advance(3 * OS_CFG_TIME_SLICE_MS); // three slices' worth of ticks
    EXPECT_EQ(holder, running());
    EXPECT_EQ(0, other.load());
    release = true;
    // The slice expired long ago: ending the section switches at once.
    EXPECT_TRUE(eventually([&] { return running() == b; }));
    power_off();
}

TEST_F(CriticalSection, InterruptsAndTimeGoOnInside) {
    std::atomic<uint32_t> t0{0}, t1{0};
    std::atomic<bool> in{false}, release{false};
    boot([&] {
        spawn([&] {
            Sys_Start_CriticalSection();
            t0 = Sys_Get_SystemTime();
            in = true;
            while (!release) {
            }
            t1 = Sys_Get_SystemTime();
            Sys_End_CriticalSection();
        });
    });
    ASSERT_TRUE(eventually([&] { return in.load(); }));
    advance(7);
    release = true;
    settle();
    EXPECT_EQ(7u, t1 - t0);
}

TEST_F(CriticalSection, PostponesEventHandlersToItsEnd) {
    boot([&] {
        Sys_Register_Event(EV_A);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM,
                               [](sys_pid, sys_event_id, const sys_event_data *) {
                                   note("handler");
                                   return true;
                               },
                               nullptr);
        spawn([] {
            Sys_Start_CriticalSection();
            Sys_Send_Event(EV_A, nullptr, 0);
            note("sent");
            Sys_End_CriticalSection();
            note("ended");
        });
    });
    settle();
    EXPECT_EQ("sent handler ended", joined());
}

TEST_F(CriticalSection, NestsAndOnlyTheOutermostEndReleases) {
    std::atomic<bool> release{false}, inner_done{false};
    std::atomic<long> other{0};
    boot([&] {
        spawn([&] {
            Sys_Start_CriticalSection();
            Sys_Start_CriticalSection();
            Sys_End_CriticalSection(); // still inside the outer one
            inner_done = true;
            while (!release) {
            }
            Sys_End_CriticalSection();
            for (;;) {
            }
        });
        spawn([&] {
            for (;;) other++;
        });
    });
    ASSERT_TRUE(eventually([&] { return inner_done.load(); }));
    advance(2 * OS_CFG_TIME_SLICE_MS);
    EXPECT_EQ(0, other.load());
    release = true;
    EXPECT_TRUE(eventually([&] { return other > 0; }));
    power_off();
}

TEST_F(CriticalSection, UnbalancedEndIsAnErrorAndDoesNotUnderflow) {
    sys_status unbalanced = SYS_OK;
    std::atomic<bool> release{false}, inside{false};
    std::atomic<long> other{0};
    boot([&] {
        spawn([&] {
            unbalanced = Sys_End_CriticalSection();
            Sys_Start_CriticalSection(); // must still protect after the bad end
            inside = true;
            while (!release) {
            }
            EXPECT_STATUS(SYS_OK, Sys_End_CriticalSection());
            for (;;) {
            }
        });
        spawn([&] {
            for (;;) other++;
        });
    });
    ASSERT_TRUE(eventually([&] { return inside.load(); }));
    advance(2 * OS_CFG_TIME_SLICE_MS);
    EXPECT_EQ(0, other.load());
    release = true;
    EXPECT_STATUS(SYS_E_INVALID, unbalanced);
    power_off();
}

TEST_F(CriticalSection, BlockingOrYieldingInsideIsRefused) {
    sys_status wait = SYS_OK, yield = SYS_OK, sleep = SYS_OK;
    boot([&] {
        Sys_Register_Event(EV_A);
        spawn([&] {
            Sys_Start_CriticalSection();
            wait = Sys_Wait_for_Event(EV_A, nullptr, 0, nullptr);
            yield = Sys_Yield();
            sleep = Sys_Sleep(5);
            Sys_End_CriticalSection();
        });
    });
    settle();
    EXPECT_STATUS(SYS_E_CONTEXT, wait);
    EXPECT_STATUS(SYS_E_CONTEXT, yield);
    EXPECT_STATUS(SYS_E_CONTEXT, sleep);
}

TEST_F(CriticalSection, ThreadEndingInsideReleasesItAndIsReported) {
    static std::atomic<int> hook_calls{0};
    static std::atomic<int> hook_fault{0};
    hook_calls = 0;
    std::atomic<long> other{0};
    boot([&] {
        Sys_Set_FaultHook([](sys_fault f, sys_pid) {
            hook_calls++;
            hook_fault = f;
        });
        spawn([] { Sys_Start_CriticalSection(); }); // returns without ending it
        spawn([&] {
            for (;;) other++;
        });
    });
    advance(2 * OS_CFG_TIME_SLICE_MS);
    EXPECT_TRUE(eventually([&] { return other > 0; })) << "scheduling goes on";
    EXPECT_EQ(1, hook_calls.load());
    EXPECT_EQ(SYS_FAULT_CRITICAL_LEAK, hook_fault.load());
    EXPECT_EQ(1u, stats().critical_leaks);
    power_off();
}

TEST_F(CriticalSection, HandlerLeavingOneOpenIsReleased) {
    std::atomic<long> a{0}, b{0};
    boot([&] {
        Sys_Register_Event(EV_A);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM,
                               [](sys_pid, sys_event_id, const sys_event_data *) {
                                   Sys_Start_CriticalSection();
                                   return true;
                               },
                               nullptr);
        spawn([&] {
            for (;;) a++;
        });
        spawn([&] {
            for (;;) b++;
        });
    });
    irq([] { Sys_Send_Event(EV_A, nullptr, 0); });
    advance(3 * OS_CFG_TIME_SLICE_MS);
    EXPECT_TRUE(eventually([&] { return a > 0 && b > 0; }));
    EXPECT_EQ(1u, stats().critical_leaks);
    power_off();
}

TEST_F(CriticalSection, InterruptsCannotOpenOne) {
    sys_status start = SYS_OK, end = SYS_OK;
    boot([] {});
    irq([&] {
        start = Sys_Start_CriticalSection();
        end = Sys_End_CriticalSection();
    });
    EXPECT_STATUS(SYS_E_CONTEXT, start);
    EXPECT_STATUS(SYS_E_CONTEXT, end);
}
