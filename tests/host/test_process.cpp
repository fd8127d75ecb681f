// Threads: creation, the five states, termination, reaping and pids.
#include "kernel_fixture.hpp"

using Process = KernelTest;

static void plain_thread() { note("plain"); }

TEST_F(Process, PaperStyleStartRunsAnArgumentlessFunction) {
    sys_pid pid = SYS_PID_NONE;
    boot([&] { pid = Sys_Start_Process(plain_thread); });
    settle();
    EXPECT_NE(SYS_PID_NONE, pid);
    EXPECT_NE(SYS_PID_SYSTEM, pid);
    EXPECT_EQ("plain", joined());
}

TEST_F(Process, EachThreadHasItsOwnPidAndKnowsIt) {
    sys_pid a = 0, b = 0;
    std::atomic<sys_pid> seen_a{0}, seen_b{0};
    boot([&] {
        a = spawn([&] { seen_a = Sys_Get_ProcessID(); });
        b = spawn([&] { seen_b = Sys_Get_ProcessID(); });
    });
    settle();
    EXPECT_NE(a, b);
    EXPECT_EQ(a, seen_a.load());
    EXPECT_EQ(b, seen_b.load());
}

TEST_F(Process, NewUntilItFirstRunsThenRunningReadyAndBlocked) {
    sys_process_state at_creation = SYS_PROCESS_ZOMBIE, self = SYS_PROCESS_ZOMBIE,
                      other = SYS_PROCESS_ZOMBIE;
    sys_pid a = 0, b = 0;
    boot([&] {
        Sys_Register_Event(EV_A);
        a = spawn([&] {
            Sys_Get_ProcessState(Sys_Get_ProcessID(), &self);
            Sys_Get_ProcessState(b, &other); // b is queued behind us
            Sys_Wait_for_Event(EV_A, nullptr, 0, nullptr);
        });
        b = spawn([] {});
        Sys_Get_ProcessState(a, &at_creation);
    });
    settle();
    EXPECT_EQ(SYS_PROCESS_NEW, at_creation);
    EXPECT_EQ(SYS_PROCESS_RUNNING, self);
    EXPECT_EQ(SYS_PROCESS_NEW, other) << "b has not run yet";
    EXPECT_EQ(SYS_PROCESS_BLOCKED, state_of(a));
}

TEST_F(Process, TheSystemThreadIsReadyWhileAThreadRunsAndRunningInItsHandlers) {
    sys_process_state from_thread = SYS_PROCESS_ZOMBIE, in_handler = SYS_PROCESS_ZOMBIE;
    static sys_process_state *seen_in_handler;
    seen_in_handler = &in_handler;
    boot([&] {
        Sys_Register_Event(EV_A);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, [](sys_pid, sys_event_id, const sys_event_data *) {
            Sys_Get_ProcessState(SYS_PID_SYSTEM, seen_in_handler);
            return true;
        }, nullptr);
        spawn([&] {
            Sys_Get_ProcessState(SYS_PID_SYSTEM, &from_thread);
            Sys_Send_Event(EV_A, nullptr, 0);
        });
    });
    settle();
    EXPECT_EQ(SYS_PROCESS_READY, from_thread) << "only one thread runs at a time";
    EXPECT_EQ(SYS_PROCESS_RUNNING, in_handler);
}

TEST_F(Process, PreemptedThreadIsReady) {
    sys_pid a = 0, b = 0;
    boot([&] {
        a = spawn([] { for (;;) {} });
        b = spawn([] { for (;;) {} });
    });
    advance(1);
    EXPECT_EQ(a, running());
    advance(OS_CFG_TIME_SLICE_MS);
    EXPECT_EQ(b, running());
    EXPECT_EQ(SYS_PROCESS_READY, state_of(a));
    power_off();
}

TEST_F(Process, KilledThreadIsAZombieUntilReaped) {
    sys_process_state during = SYS_PROCESS_NEW;
    sys_status after = SYS_OK;
    sys_pid victim = 0;
    boot([&] {
        Sys_Register_Event(EV_A);
        victim = spawn([] { Sys_Wait_for_Event(EV_A, nullptr, 0, nullptr); });
        spawn([&] {
            Sys_Start_CriticalSection(); // postpones the reaping
            EXPECT_STATUS(SYS_OK, Sys_Kill_Process(victim));
            Sys_Get_ProcessState(victim, &during);
            Sys_End_CriticalSection();
            after = Sys_Get_ProcessState(victim, nullptr);
        });
    });
    settle();
    EXPECT_EQ(SYS_PROCESS_ZOMBIE, during);
    EXPECT_STATUS(SYS_E_INVALID, after);
}

TEST_F(Process, ReturningThreadIsReapedAndItsSlotReused) {
    std::atomic<int> ran{0};
    boot([&] {
        // Far more threads over time than slots at once.
        spawn([&] {
            for (int i = 0; i < 3 * OS_CFG_MAX_THREADS; i++) {
                sys_pid pid = SYS_PID_NONE;
                ASSERT_STATUS(SYS_OK, Sys_Start_Process_Ex([](void *r) { ++*static_cast<std::atomic<int> *>(r); },
                                                          &ran, 0, 0, &pid));
                Sys_Yield(); // let it run, end and be reaped
            }
        });
    });
    settle();
    EXPECT_EQ(3 * OS_CFG_MAX_THREADS, ran.load());
    EXPECT_EQ(0u, stats().process_pool_full);
}

TEST_F(Process, KilledReadyThreadNeverRuns) {
    boot([&] {
        sys_pid victim = spawn([] { note("victim ran"); });
        EXPECT_STATUS(SYS_OK, Sys_Kill_Process(victim));
    });
    settle();
    EXPECT_EQ("", joined());
}

TEST_F(Process, ThreadCanKillItself) {
    boot([&] {
        spawn([] {
            note("before");
            Sys_Kill_Process(Sys_Get_ProcessID());
            note("after");
        });
    });
    settle();
    EXPECT_EQ("before", joined());
}

TEST_F(Process, InvalidAndStalePidsAreRejected) {
    sys_pid first = 0, second = 0;
    sys_status kill_system = SYS_OK, kill_garbage = SYS_OK, kill_stale = SYS_OK;
    boot([&] {
        first = spawn([] {});
        spawn([&] {
            // first has ended and been reaped; its slot goes to the next thread.
            second = spawn([] { Sys_Sleep(1000); });
            kill_stale = Sys_Kill_Process(first);
            kill_system = Sys_Kill_Process(SYS_PID_SYSTEM);
            kill_garbage = Sys_Kill_Process(0x0F);
        });
    });
    settle();
    EXPECT_EQ(first & 0x0F, second & 0x0F) << "the slot was reused";
    EXPECT_NE(first, second) << "with a new generation";
    EXPECT_STATUS(SYS_E_INVALID, kill_stale);
    EXPECT_STATUS(SYS_E_INVALID, kill_system);
    EXPECT_STATUS(SYS_E_INVALID, kill_garbage);
    EXPECT_EQ(SYS_PROCESS_BLOCKED, state_of(second)) << "the stale kill did not hit the new thread";
}

TEST_F(Process, BadArgumentsAreRejected) {
    sys_status null_fn = SYS_OK, bad_state = SYS_OK, bad_priority = SYS_OK;
    sys_pid plain_null = 0;
    boot([&] {
        sys_pid pid;
        null_fn = Sys_Start_Process_Ex(nullptr, nullptr, 0, 0, &pid);
        plain_null = Sys_Start_Process(nullptr);
        bad_state = Sys_Get_ProcessState(0x0E, nullptr);
        bad_priority = Sys_Set_Priority(0x0E, 3);
    });
    settle();
    EXPECT_STATUS(SYS_E_INVALID, null_fn);
    EXPECT_EQ(SYS_PID_NONE, plain_null);
    EXPECT_STATUS(SYS_E_INVALID, bad_state);
    EXPECT_STATUS(SYS_E_INVALID, bad_priority);
}

// The system thread is never queued: from a thread, a priority for it put
// it in the ready list among the threads (it returned SYS_OK).
TEST_F(Process, SystemThreadPriorityIsRefused) {
    sys_status from_thread = SYS_OK, from_main = SYS_OK;
    boot([&] {
        from_main = Sys_Set_Priority(SYS_PID_SYSTEM, 1);
        Sys_Set_Scheduler(&sys_scheduler_priority);
        spawn([&] {
            from_thread = Sys_Set_Priority(SYS_PID_SYSTEM, 9);
            note("ran on");
        });
    });
    settle();
    EXPECT_STATUS(SYS_E_INVALID, from_main);
    EXPECT_STATUS(SYS_E_INVALID, from_thread);
    EXPECT_EQ("ran on", joined());
}

TEST_F(Process, YieldAlternatesBetweenReadyThreads) {
    boot([&] {
        spawn([] {
            for (int i = 0; i < 3; i++) {
                note("a");
                EXPECT_STATUS(SYS_OK, Sys_Yield());
            }
        });
        spawn([] {
            for (int i = 0; i < 3; i++) {
                note("b");
                EXPECT_STATUS(SYS_OK, Sys_Yield());
            }
        });
    });
    settle();
    EXPECT_EQ("a b a b a b", joined());
}

// Each yield to the other ready thread and back is two switches, counted
// past 255 and 511 (the count's low byte carries into the others).
TEST_F(Process, SwitchCountCountsEverySwitchPastItsLowByte) {
    uint32_t counted = 0;
    boot([&] {
        spawn([&] {
            uint32_t before = Sys_Get_SwitchCount();
            for (int i = 0; i < 300; i++) Sys_Yield();
            counted = Sys_Get_SwitchCount() - before;
        });
        spawn([] {
            for (int i = 0; i < 400; i++) Sys_Yield(); // outlasts the first
        });
    });
    settle();
    EXPECT_EQ(600u, counted);
}

TEST_F(Process, YieldAloneReturnsAtOnce) {
    boot([&] {
        spawn([] {
            EXPECT_STATUS(SYS_OK, Sys_Yield());
            note("back");
        });
    });
    settle();
    EXPECT_EQ("back", joined());
}

TEST_F(Process, YieldOutsideAThreadIsAContextError) {
    sys_status from_setup = SYS_OK, from_isr = SYS_OK;
    boot([&] { from_setup = Sys_Yield(); });
    settle();
    irq([&] { from_isr = Sys_Yield(); });
    EXPECT_STATUS(SYS_E_CONTEXT, from_setup);
    EXPECT_STATUS(SYS_E_CONTEXT, from_isr);
}

TEST_F(Process, ExplicitStackSizeIsHonoured) {
    std::atomic<int> sum{0};
    boot([&] {
        spawn(
            [&] {
                volatile uint8_t big[900];
                for (unsigned i = 0; i < sizeof big; i++) big[i] = (uint8_t)i;
                int s = 0;
                for (unsigned i = 0; i < sizeof big; i++) s += big[i];
                sum = s;
            },
            0, 1024);
    });
    settle();
    int expected = 0;
    for (unsigned i = 0; i < 900; i++) expected += (uint8_t)i;
    EXPECT_EQ(expected, sum.load());
    EXPECT_EQ(0u, stats().stack_overflows);
}

TEST_F(Process, ThreadsCanBeStartedFromHandlersAndInterrupts) {
    boot([&] {
        Sys_Register_Event(EV_A);
        Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM,
                               [](sys_pid, sys_event_id, const sys_event_data *) {
                                   Sys_Start_Process([] { note("from handler"); });
                                   return true;
                               },
                               nullptr);
    });
    settle();
    irq([] { Sys_Start_Process([] { note("from interrupt"); }); });
    settle();
    irq([] { Sys_Send_Event(EV_A, nullptr, 0); });
    settle();
    EXPECT_EQ("from interrupt from handler", joined());
}
