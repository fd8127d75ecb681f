// Test fixture: boots the kernel on the host port's simulated CPU with a
// manual clock, so the test decides when every tick and interrupt happens.
#pragma once

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>
#include <functional>
#include <string>
#include <vector>

extern "C" {
#include "openswarm/host.h"
#include "openswarm/kernel.h"
}

// Lets EXPECT_EQ print status names instead of numbers.
struct Status {
    sys_status value;
    bool operator==(const Status &o) const { return value == o.value; }
};
inline std::ostream &operator<<(std::ostream &os, const Status &s) {
    return os << Sys_Status_Name(s.value);
}
#define EXPECT_STATUS(expected, call) EXPECT_EQ(Status{expected}, Status{(call)})
#define ASSERT_STATUS(expected, call) ASSERT_EQ(Status{expected}, Status{(call)})

// What the code on the CPU did, in order; the test reads it once the CPU is
// idle (or through an interrupt).
inline std::vector<std::string> &trace() {
    static std::vector<std::string> t;
    return t;
}
inline void note(const std::string &what) { trace().push_back(what); }
inline std::string joined() {
    std::string s;
    for (const auto &t : trace()) s += (s.empty() ? "" : " ") + t;
    return s;
}

class KernelTest : public ::testing::Test {
protected:
    void SetUp() override { trace().clear(); }

    // Runs on the CPU between Sys_Init_Kernel and Sys_Start_Kernel.
    void boot(std::function<void()> setup, host_clock clock = HOST_CLOCK_MANUAL) {
        setup_ = std::move(setup);
        current_ = this;
        host_cpu_start(clock, [] { current_->setup_(); });
        running_ = true;
    }

    // Tests whose threads still run at the end (spinning on the test's
    // locals) must power off before those locals go out of scope.
    void power_off() {
        if (running_) host_cpu_stop();
        running_ = false;
    }

    void TearDown() override { power_off(); }

    // Runs f on the CPU as an interrupt service routine.
    static void irq(std::function<void()> f) {
        host_cpu_interrupt([](void *p) { (*static_cast<std::function<void()> *>(p))(); }, &f);
    }

    static void advance(uint32_t ms) { host_cpu_advance(ms); }

    // For what a running thread does after an interrupt was serviced: wait
    // (bounded) until pred holds. Tests never rely on it for timing.
    static bool eventually(const std::function<bool()> &pred) {
        for (int i = 0; i < 100000; i++) {
            if (pred()) return true;
            std::this_thread::sleep_for(std::chrono::microseconds(100));
        }
        return pred();
    }

    static void settle() { ASSERT_TRUE(host_cpu_wait_idle(10000)) << "the CPU never went idle"; }

    // Start a thread running f (call from the CPU: setup, a thread, a handler).
    sys_pid spawn(std::function<void()> f, uint8_t priority = SYS_PRIORITY_DEFAULT,
                  uint16_t stack = 0) {
        bodies_.push_back(std::make_unique<std::function<void()>>(std::move(f)));
        sys_pid pid = SYS_PID_NONE;
        sys_status st = Sys_Start_Process_Ex(
            [](void *p) { (*static_cast<std::function<void()> *>(p))(); }, bodies_.back().get(),
            stack, priority, &pid);
        EXPECT_STATUS(SYS_OK, st);
        return pid;
    }

    static sys_process_state state_of(sys_pid pid) {
        sys_process_state s = SYS_PROCESS_ZOMBIE;
        sys_status st = SYS_E_INVALID;
        irq([&] { st = Sys_Get_ProcessState(pid, &s); });
        EXPECT_STATUS(SYS_OK, st) << "pid " << int(pid);
        return s;
    }

    static bool alive(sys_pid pid) {
        sys_status st = SYS_OK;
        irq([&] { st = Sys_Get_ProcessState(pid, nullptr); });
        return st == SYS_OK;
    }

    // The thread the CPU is running (as an interrupt sees it).
    static sys_pid running() {
        sys_pid p = SYS_PID_NONE;
        irq([&] { p = Sys_Get_ProcessID(); });
        return p;
    }

    static sys_stats stats() {
        sys_stats s{};
        irq([&] { Sys_Get_Stats(&s); });
        return s;
    }

private:
    std::function<void()> setup_;
    std::vector<std::unique_ptr<std::function<void()>>> bodies_;
    bool running_ = false;
    static inline KernelTest *current_ = nullptr;
};

// Event ids for tests.
constexpr sys_event_id EV_A = SYS_EVENT_FIRST_FREE;
constexpr sys_event_id EV_B = SYS_EVENT_FIRST_FREE + 1;
constexpr sys_event_id EV_C = SYS_EVENT_FIRST_FREE + 2;
