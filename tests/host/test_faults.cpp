// Stack overflow detection: the guard is checked at every scheduling decision
// a thread makes and at every tick that leads to one; a broken one is
// reported by the port, through the fault hook and through SYS_EVENT_FAULT.
// And the watch on handlers that never return.
#include "kernel_fixture.hpp"

#include <cstring>

#include "openswarm/port_arch.h"


static std::atomic<int> hook_calls{0};
static std::atomic<int> hook_fault{0};
static std::atomic<sys_pid> hook_pid{SYS_PID_NONE};
static std::atomic<int> event_fault{0};
static std::atomic<sys_pid> event_pid{SYS_PID_NONE};

// Writes well below its own stack frame: past the bottom of a stack of
// `stack` bytes (+ the port's extra), into the guard and beyond. The
// sanitizer is told to let it: the overflow is the point of the test.
__attribute__((no_sanitize_address, noinline)) static void overflow_stack(size_t stack) {
    volatile uint8_t here = 0;
    volatile uint8_t *volatile p = &here; // opaque to the compiler's bounds checks
    size_t reach = stack + PORT_STACK_EXTRA + 64;
    for (size_t i = 256; i < reach; i++) p[-(ptrdiff_t)i] = 0xEE;
}

struct Faults : KernelTest {
    // While booting: a thread that overflows its 256-byte stack, then spins.
    // A spacer below its stack, killed before the overflow, makes the
    // overflow land in free pool memory rather than in a live stack.
    sys_pid start_overflowing_thread(std::atomic<bool> &overflowed, std::atomic<long> &spins) {
        sys_pid spacer = spawn([] { Sys_Sleep(1000000); }, 0, 256);
        sys_pid victim = spawn(
            [&] {
                overflow_stack(256);
                overflowed = true;
                for (;;) spins++;
            },
            0, 256);
        Sys_Kill_Process(spacer);
        return victim;
    }
};

#if OS_CFG_STACK_CHECK
TEST_F(Faults, StackOverflowIsDetectedReportedAndTheThreadKilled) {
    testing::internal::CaptureStderr(); // the host port reports faults there
    hook_calls = 0;
    event_fault = 0;
    std::atomic<bool> overflowed{false};
    std::atomic<long> spins{0}, bystander{0};
    sys_pid victim = 0;
    boot([&] {
        Sys_Set_FaultHook([](sys_fault f, sys_pid pid) {
            hook_calls++;
            hook_fault = f;
            hook_pid = pid;
        });
        Sys_Subscribe_to_Event(SYS_EVENT_FAULT, SYS_PID_SYSTEM,
                               [](sys_pid, sys_event_id, const sys_event_data *d) {
                                   sys_fault_info info;
                                   std::memcpy(&info, d->value, sizeof info);
                                   event_fault = info.fault;
                                   event_pid = info.pid;
                                   return true;
                               },
                               nullptr);
        victim = start_overflowing_thread(overflowed, spins);
        spawn([&] {
            for (;;) bystander++;
        });
    });
    ASSERT_TRUE(eventually([&] { return overflowed.load(); }));
    advance(OS_CFG_TIME_SLICE_MS); // the switch at the end of its slice checks the guard
    ASSERT_TRUE(eventually([&] { return event_fault != 0; }));
    EXPECT_EQ(1, hook_calls.load());
    EXPECT_EQ(SYS_FAULT_STACK_OVERFLOW, hook_fault.load());
    EXPECT_EQ(victim, hook_pid.load());
    EXPECT_EQ(SYS_FAULT_STACK_OVERFLOW, event_fault.load());
    EXPECT_EQ(victim, event_pid.load());
    EXPECT_FALSE(alive(victim));
    EXPECT_EQ(1u, stats().stack_overflows);
    std::string err = testing::internal::GetCapturedStderr(); // ASan may add its own notes
    EXPECT_NE(std::string::npos,
              err.find("openswarm: kernel fault: stack overflow in thread " + std::to_string(victim) + "\n"))
        << err;
    long before = bystander;
    advance(2 * OS_CFG_TIME_SLICE_MS);
    EXPECT_TRUE(eventually([&] { return bystander > before; })) << "the others go on";
    power_off();
}

// With no other thread ready, the end of its slice only renews it (the
// quiet tick's way): the guard is checked there too.
TEST_F(Faults, AnOverflowingThreadThatSpinsAloneIsStoppedWithinASlice) {
    testing::internal::CaptureStderr();
    std::atomic<bool> overflowed{false};
    std::atomic<long> spins{0};
    sys_pid victim = 0;
    boot([&] { victim = start_overflowing_thread(overflowed, spins); });
    ASSERT_TRUE(eventually([&] { return overflowed.load(); }));
    advance(OS_CFG_TIME_SLICE_MS);
    EXPECT_TRUE(eventually([&] { return !alive(victim); }));
    EXPECT_EQ(1u, stats().stack_overflows);
    testing::internal::GetCapturedStderr();
    power_off();
}
#else
// OS_CFG_STACK_CHECK 0 (config.h): no guard and no check, so the same
// overflow (into free pool memory) raises no fault and the thread runs on.
TEST_F(Faults, StackOverflowGoesUnnoticedWithoutTheCheck) {
    hook_calls = 0;
    event_fault = 0;
    std::atomic<bool> overflowed{false};
    std::atomic<long> spins{0};
    sys_pid victim = 0;
    boot([&] {
        Sys_Set_FaultHook([](sys_fault, sys_pid) { hook_calls++; });
        Sys_Subscribe_to_Event(SYS_EVENT_FAULT, SYS_PID_SYSTEM,
                               [](sys_pid, sys_event_id, const sys_event_data *) {
                                   event_fault = 1;
                                   return true;
                               },
                               nullptr);
        victim = start_overflowing_thread(overflowed, spins);
        spawn([] {
            for (;;) {
            }
        });
    });
    ASSERT_TRUE(eventually([&] { return overflowed.load(); }));
    for (int slice = 0; slice < 4; slice++) {
        long before = spins;
        advance(2 * OS_CFG_TIME_SLICE_MS); // switches, ticks: where a check would be
        EXPECT_TRUE(eventually([&] { return spins > before; })) << "it runs on";
    }
    EXPECT_TRUE(alive(victim));
    EXPECT_EQ(0, hook_calls.load());
    EXPECT_EQ(0, event_fault.load());
    EXPECT_EQ(0u, stats().stack_overflows);
    power_off();
}
#endif

TEST_F(Faults, AThreadWithinItsStackRaisesNoFault) {
    hook_calls = 0;
    std::atomic<int> depth{0};
    boot([&] {
        Sys_Set_FaultHook([](sys_fault, sys_pid) { hook_calls++; });
        spawn(
            [&] {
                for (int round = 0; round < 50; round++) {
                    volatile uint8_t buf[200];
                    for (auto &b : buf) b = (uint8_t)round;
                    depth = buf[199];
                    Sys_Yield();
                }
            },
            0, 256);
        spawn([] {
            for (int i = 0; i < 50; i++) Sys_Yield();
        });
    });
    settle();
    EXPECT_EQ(49, depth.load());
    EXPECT_EQ(0, hook_calls.load());
    EXPECT_EQ(0u, stats().stack_overflows);
}

// A handler that never returns is reported once, when it has run
// OS_CFG_HANDLER_LIMIT_MS ticks: counted from its start, although the tick
// had counted ahead without looking (no deadline in sight) when it began.
// The real-time clock: the manual one waits for each tick's end, which a
// spinning handler never lets come.
TEST_F(Faults, AHandlerOverrunIsReportedAtTheLimitFromItsStart) {
    testing::internal::CaptureStderr(); // the host port reports faults there
    static std::atomic<bool> release;
    static std::atomic<uint32_t> began, reported;
    release = false;
    began = reported = 0;
    hook_calls = 0;
    boot(
        [&] {
            Sys_Set_FaultHook([](sys_fault f, sys_pid) {
                if (f == SYS_FAULT_HANDLER_OVERRUN) reported = Sys_Get_SystemTime();
                hook_calls++;
            });
            Sys_Register_Event(EV_A);
            Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM,
                                   [](sys_pid, sys_event_id, const sys_event_data *) {
                                       began = Sys_Get_SystemTime();
                                       while (!release) {
                                       }
                                       return true;
                                   },
                                   nullptr);
            spawn([] {
                Sys_Sleep(300);
                Sys_Send_Event(EV_A, nullptr, 0);
            });
        },
        HOST_CLOCK_REALTIME);
    EXPECT_TRUE(eventually([&] { return reported != 0; }));
    release = true;
    EXPECT_GE(began.load(), 300u);
    EXPECT_EQ(uint32_t{OS_CFG_HANDLER_LIMIT_MS}, reported - began);
    EXPECT_EQ(1, hook_calls.load()) << "said once";
    EXPECT_EQ(1u, stats().handler_overruns);
    power_off();
    testing::internal::GetCapturedStderr();
}

// The names the ports' consoles print ("kernel fault: stack overflow in
// thread 3"), and one for what no fault is.
TEST(FaultNames, EachFaultHasTheConsolesName) {
    EXPECT_STREQ("stack overflow", Sys_Fault_Name(SYS_FAULT_STACK_OVERFLOW));
    EXPECT_STREQ("critical section left open", Sys_Fault_Name(SYS_FAULT_CRITICAL_LEAK));
    EXPECT_STREQ("CPU fault", Sys_Fault_Name(SYS_FAULT_CPU));
    EXPECT_STREQ("an event handler ran past its limit", Sys_Fault_Name(SYS_FAULT_HANDLER_OVERRUN));
    EXPECT_STREQ("fault", Sys_Fault_Name(0));
    EXPECT_STREQ("fault", Sys_Fault_Name(200));
}
