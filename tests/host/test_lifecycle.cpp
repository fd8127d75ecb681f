// Initialising, starting and stopping the kernel; the system thread.
#include "kernel_fixture.hpp"

using Lifecycle = KernelTest;

TEST_F(Lifecycle, SystemThreadIsPidZeroAndIdlesWithNothingToDo) {
    sys_pid in_setup = SYS_PID_NONE;
    boot([&] { in_setup = Sys_Get_ProcessID(); });
    settle();
    EXPECT_EQ(SYS_PID_SYSTEM, in_setup);
    EXPECT_EQ(SYS_PROCESS_RUNNING, state_of(SYS_PID_SYSTEM));
}

TEST_F(Lifecycle, ThreadsStartedBeforeTheKernelRunOnceItStarts) {
    boot([&] {
        spawn([] { note("a"); });
        spawn([] { note("b"); });
        note("setup");
    });
    settle();
    EXPECT_EQ("setup a b", joined());
}

TEST_F(Lifecycle, KernelEventsAreRegisteredByInit) {
    bool timer = false, fault = false, user = true;
    boot([&] {
        timer = Sys_IsEventRegistered(SYS_EVENT_1MS_TIMER);
        fault = Sys_IsEventRegistered(SYS_EVENT_FAULT);
        user = Sys_IsEventRegistered(EV_A);
    });
    settle();
    EXPECT_EQ(OS_CFG_CLOCK_EVENT == 1, timer) << "unless configured out (config.h)";
    EXPECT_TRUE(fault);
    EXPECT_FALSE(user);
}

TEST_F(Lifecycle, StopKernelReturnsFromTheSystemThreadEvenWithABusyThread) {
    std::atomic<bool> spinning{false};
    boot([&] {
        spawn([&] {
            spinning = true;
            for (;;) {
            }
        });
    });
    advance(1);
    while (!spinning) advance(1);
    // TearDown stops the CPU; reaching the end of this test proves it.
    power_off();
}

TEST_F(Lifecycle, ReinitialisingStartsFromScratch) {
    sys_pid first = SYS_PID_NONE;
    boot([&] {
        Sys_Register_Event(EV_A);
        first = spawn([] {});
    });
    settle();
    host_cpu_stop();
    bool registered = true;
    sys_pid second = SYS_PID_NONE;
    boot([&] {
        registered = Sys_IsEventRegistered(EV_A);
        second = spawn([] {});
    });
    settle();
    EXPECT_FALSE(registered);
    EXPECT_EQ(first, second) << "a fresh kernel hands out the same first pid";
}
