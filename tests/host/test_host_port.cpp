// The host port itself: real preemption of threads that never yield, with
// the manual clock and with the real-time clock; idling.
#include "kernel_fixture.hpp"

using HostPort = KernelTest;

TEST_F(HostPort, ThreadsThatNeverYieldArePreempted) {
    std::atomic<long> a{0}, b{0}, c{0};
    boot([&] {
        spawn([&] {
            for (;;) a++;
        });
        spawn([&] {
            for (;;) b++;
        });
        spawn([&] {
            for (;;) c++;
        });
    });
    advance(3 * OS_CFG_TIME_SLICE_MS);
    EXPECT_TRUE(eventually([&] { return a > 0 && b > 0 && c > 0; }));
    uint32_t switches = 0;
    irq([&] { switches = Sys_Get_SwitchCount(); });
    EXPECT_GE(switches, 3u);
    power_off();
}

TEST_F(HostPort, RealTimeClockTicksAndPreempts) {
    std::atomic<long> a{0}, b{0};
    std::atomic<uint32_t> now{0};
    boot(
        [&] {
            spawn([&] {
                for (;;) a++;
            });
            spawn([&] {
                for (;;) {
                    b++;
                    now = Sys_Get_SystemTime();
                }
            });
        },
        HOST_CLOCK_REALTIME);
    // Wall-clock bounded, not timed: passes as soon as both have run and
    // 50 ticks have gone by, however slow the machine.
    EXPECT_TRUE(eventually([&] { return a > 0 && b > 0 && now >= 50; }));
    power_off();
}

TEST_F(HostPort, IdleCpuWakesForTicksAndKeepsTime) {
    uint32_t t = 0;
    boot([] {});
    settle();
    advance(25);
    settle();
    irq([&] { t = Sys_Get_SystemTime(); });
    EXPECT_EQ(25u, t);
}

TEST_F(HostPort, InterruptsRunInInterruptContext) {
    sys_status wait = SYS_OK;
    boot([] { Sys_Register_Event(EV_A); });
    irq([&] { wait = Sys_Wait_for_Event(EV_A, nullptr, 0, nullptr); });
    EXPECT_STATUS(SYS_E_CONTEXT, wait);
}
