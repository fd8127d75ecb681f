// A program on the system thread (Sys_Run_SystemProgram, kernel/src/
// system_program.c): kilolib's setup()/loop() run this way, on main's
// stack with no thread of their own. Handlers preempt the program, on its
// stack; it waits with Sys_Idle, where the kernel dispatches, lets the
// ready threads run, or sleeps at most as long as it is told.
#include "kernel_fixture.hpp"

namespace {

std::function<void()> program_setup, program_body;
std::atomic<bool> program_done{false};

int program_main() {
    Sys_Init_Kernel();
    program_setup();
    Sys_Start_Kernel();
    Sys_Run_SystemProgram([] {
        program_body();
        program_done = true;
    });
    return 0;
}

class SystemProgram : public KernelTest {
protected:
    void run(std::function<void()> setup, std::function<void()> body) {
        program_setup = std::move(setup);
        program_body = std::move(body);
        program_done = false;
        host_cpu_start_main(HOST_CLOCK_MANUAL, program_main);
        started_ = true;
    }
    void TearDown() override {
        if (started_) host_cpu_stop();
    }

private:
    bool started_ = false;
};

std::atomic<bool> heard{false};
std::atomic<int> in_program_from_handler{-1};

bool on_a(sys_pid, sys_event_id, const sys_event_data *) {
    note("handler");
    in_program_from_handler = Sys_In_SystemProgram();
    heard = true;
    return true;
}

} // namespace

TEST_F(SystemProgram, ItsOwnSendIsHandledBeforeTheSendReturns) {
    run([] {
            Sys_Register_Event(EV_A);
            Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, on_a, nullptr);
        },
        [] {
            EXPECT_TRUE(Sys_In_SystemProgram());
            note("send");
            EXPECT_STATUS(SYS_OK, Sys_Send_Event(EV_A, nullptr, 0));
            note("sent");
        });
    ASSERT_TRUE(eventually([] { return program_done.load(); }));
    EXPECT_EQ("send handler sent", joined()) << "the handler ran nested on the program's stack";
    EXPECT_EQ(0, in_program_from_handler.load()) << "a handler is not the program";
}

TEST_F(SystemProgram, AnInterruptsEventReachesAWaitingProgram) {
    heard = false;
    run([] {
            Sys_Register_Event(EV_A);
            Sys_Subscribe_to_Event(EV_A, SYS_PID_SYSTEM, on_a, nullptr);
        },
        [] {
            int turns = 0;
            while (!heard) {
                EXPECT_STATUS(SYS_OK, Sys_Idle(1000));
                turns++;
            }
            note(turns > 0 ? "woke" : "never waited");
        });
    settle();
    EXPECT_FALSE(program_done.load()) << "nothing came yet: the program waits";
    irq([] { Sys_Send_Event(EV_A, nullptr, 0); });
    ASSERT_TRUE(eventually([] { return program_done.load(); }));
    EXPECT_EQ("handler woke", joined());
}

TEST_F(SystemProgram, IdleSleepsAtMostItsTime) {
    static std::atomic<uint32_t> slept{0};
    run([] {},
        [] {
            uint32_t from = Sys_Get_SystemTime();
            EXPECT_STATUS(SYS_OK, Sys_Idle(5));
            slept = Sys_Get_SystemTime() - from;
        });
    settle();
    EXPECT_FALSE(program_done.load()) << "asleep until 5 ms pass";
    advance(5);
    ASSERT_TRUE(eventually([] { return program_done.load(); }));
    EXPECT_GE(slept.load(), 1u);
    EXPECT_LE(slept.load(), 5u);
}

TEST_F(SystemProgram, ThreadsRunWhileItWaitsAndNeverElsewhere) {
    static std::atomic<int> thread_context{-1};
    run([this] {
            spawn([] {
                note("thread");
                thread_context = Sys_In_SystemProgram();
                EXPECT_STATUS(SYS_E_CONTEXT, Sys_Idle(1)) << "a thread cannot idle as the program";
            });
        },
        [] {
            note("program");
            EXPECT_STATUS(SYS_OK, Sys_Idle(1000)); // the ready thread runs to its end here
            note("back");
        });
    ASSERT_TRUE(eventually([] { return program_done.load(); }));
    EXPECT_EQ("program thread back", joined());
    EXPECT_EQ(0, thread_context.load());
}

TEST_F(SystemProgram, IdleOutsideTheProgramIsRefused) {
    static std::atomic<int> handler_status{0};
    run([] {
            Sys_Register_Event(EV_A);
            Sys_Subscribe_to_Event(
                EV_A, SYS_PID_SYSTEM,
                [](sys_pid, sys_event_id, const sys_event_data *) {
                    handler_status = Sys_Idle(1);
                    return true;
                },
                nullptr);
        },
        [] { Sys_Send_Event(EV_A, nullptr, 0); });
    ASSERT_TRUE(eventually([] { return program_done.load(); }));
    EXPECT_STATUS(SYS_E_CONTEXT, (sys_status)handler_status.load());
    sys_status from_interrupt = SYS_OK;
    irq([&] { from_interrupt = Sys_Idle(1); });
    EXPECT_STATUS(SYS_E_CONTEXT, from_interrupt);
}
