// System time, sleeping, and the 1 ms timer event (the paper's Listing 1
// waits on it with a condition that counts occurrences).
#include "kernel_fixture.hpp"

#include <cstring>

using Time = KernelTest;

namespace {

// Tick by tick, letting the CPU finish each tick's work (dispatch, the
// threads it woke) before the next one, as 1 ms is plenty on a robot.
void ticks(uint32_t n) {
    for (uint32_t i = 0; i < n; i++) {
        host_cpu_advance(1);
        ASSERT_TRUE(host_cpu_wait_idle(10000)) << "the CPU never went idle";
    }
}

#if OS_CFG_CLOCK_EVENT
// Listing 1's wait250times, counting the occurrences it is shown. (The
// paper's `counter++ < 250` would accept the 251st.)
int occurrences = 0;
bool wait250times(const sys_event_data *) {
    if (++occurrences < 250) return false;
    occurrences = 0;
    return true;
}
#endif

} // namespace

TEST_F(Time, SystemTimeAdvancesByOnePerTick) {
    auto now = [] {
        uint32_t t = 0xFFFFFFFF;
        irq([&] { t = Sys_Get_SystemTime(); });
        return t;
    };
    boot([] {});
    settle();
    EXPECT_EQ(0u, now()) << "the manual clock does not tick by itself";
    for (uint32_t i = 1; i <= 20; i++) {
        advance(1);
        EXPECT_EQ(i, now());
    }
    advance(100);
    EXPECT_EQ(120u, now());
    settle();
    EXPECT_EQ(120u, now()) << "idling costs no time";
}

TEST_F(Time, SleepBlocksForExactlyTheRequestedTicks) {
    std::vector<uint32_t> slept;
    std::atomic<int> woke{0};
    const uint32_t durations[] = {1, 7, 30};
    sys_pid sleeper = SYS_PID_NONE;
    boot([&] {
        sleeper = spawn([&] {
            for (uint32_t ms : durations) {
                uint32_t before = Sys_Get_SystemTime();
                EXPECT_STATUS(SYS_OK, Sys_Sleep(ms));
                slept.push_back(Sys_Get_SystemTime() - before);
                woke++;
            }
            Sys_Sleep(1000000);
        });
    });
    settle();
    int expected = 0;
    for (uint32_t ms : durations) {
        ticks(ms - 1);
        EXPECT_EQ(expected, woke.load()) << "woke early from Sys_Sleep(" << ms << ")";
        EXPECT_EQ(SYS_PROCESS_BLOCKED, state_of(sleeper));
        ticks(1);
        EXPECT_EQ(++expected, woke.load()) << "still asleep after " << ms << " ticks";
    }
    EXPECT_EQ((std::vector<uint32_t>{1, 7, 30}), slept);
}

TEST_F(Time, SleepersWakeInTheOrderOfTheirDeadlines) {
    boot([&] {
        spawn([] {
            Sys_Sleep(5);
            note("a@" + std::to_string(Sys_Get_SystemTime()));
        });
        spawn([] {
            Sys_Sleep(3);
            note("b@" + std::to_string(Sys_Get_SystemTime()));
        });
    });
    settle();
    ticks(10);
    EXPECT_EQ("b@3 a@5", joined());
}

// The tick visits the timed waits only when the nearest is due; a wait that
// starts, or ends early, in between must leave every other deadline exact.
TEST_F(Time, DeadlinesStayExactAsWaitsComeAndGo) {
    boot([&] {
        Sys_Register_Event(EV_A);
        spawn([] {
            Sys_Sleep(10);
            note("a@" + std::to_string(Sys_Get_SystemTime()));
        });
        spawn([] {
            Sys_Sleep(3); // starts the next wait while a counts down
            Sys_Sleep(4);
            note("b@" + std::to_string(Sys_Get_SystemTime()));
        });
        spawn([] {
            sys_status st = Sys_Wait_for_Event_Timeout(EV_A, 2, nullptr, 0, nullptr);
            note("c" + std::string(st == SYS_E_TIMEOUT ? "-timeout" : "-event") + "@" +
                 std::to_string(Sys_Get_SystemTime()));
            st = Sys_Wait_for_Event_Timeout(EV_A, 50, nullptr, 0, nullptr); // ended early below
            note("c" + std::string(st == SYS_E_TIMEOUT ? "-timeout" : "-event") + "@" +
                 std::to_string(Sys_Get_SystemTime()));
            Sys_Sleep(6);
            note("c@" + std::to_string(Sys_Get_SystemTime()));
        });
    });
    settle();
    ticks(5);
    irq([] { Sys_Send_Event(EV_A, nullptr, 0); }); // at 5: ends c's 50 ms wait
    settle();
    ticks(10);
    EXPECT_EQ("c-timeout@2 c-event@5 b@7 a@10 c@11", joined());
}

// Most ticks count the time alone, up to the next one a deadline needs, a
// byte's worth at most (system_time.c): the time and far deadlines stay
// exact across as many of those as they take, and the clock across its
// lowest byte's wraps (at 256, 512, 768, 1024 and 1280).
TEST_F(Time, FarDeadlinesAndTheTimeStayExactPastWhatAByteCounts) {
    const uint32_t durations[] = {255, 256, 257, 600};
    boot([&] {
        spawn([&] {
            for (uint32_t ms : durations) {
                uint32_t before = Sys_Get_SystemTime();
                Sys_Sleep(ms);
                uint32_t now = Sys_Get_SystemTime();
                note(std::to_string(now - before) + "@" + std::to_string(now));
            }
        });
    });
    settle();
    ticks(1368);
    EXPECT_EQ("255@255 256@511 257@768 600@1368", joined());
    uint32_t now = 0;
    irq([&] { now = Sys_Get_SystemTime(); });
    EXPECT_EQ(1368u, now);
}

// A deadline sooner than the next one the tick expects: at 300, the tick
// that ends b's sleep finds the next deadline (a's) 700 ms away and counts
// the ticks up to a byte's worth without looking; b's 5 ms sleep, started
// then, still ends at 305.
TEST_F(Time, ASleepStartedWhenTheNextDeadlineIsFarEndsOnTime) {
    boot([&] {
        spawn([] { Sys_Sleep(1000); });
        spawn([] {
            Sys_Sleep(300);
            note("woke@" + std::to_string(Sys_Get_SystemTime()));
            Sys_Sleep(5);
            note("slept@" + std::to_string(Sys_Get_SystemTime()));
        });
    });
    settle();
    ticks(320);
    EXPECT_EQ("woke@300 slept@305", joined());
}

TEST_F(Time, SleepZeroReturnsAtOnceAndSleepOutsideAThreadIsRefused) {
    sys_status in_setup = SYS_OK, in_irq = SYS_OK, zero = SYS_E_INVALID;
    boot([&] {
        in_setup = Sys_Sleep(1);
        spawn([&] {
            zero = Sys_Sleep(0);
            note("after sleep(0)");
        });
    });
    settle();
    irq([&] { in_irq = Sys_Sleep(1); });
    EXPECT_STATUS(SYS_OK, zero);
    EXPECT_EQ("after sleep(0)", joined()) << "without any tick";
    EXPECT_STATUS(SYS_E_CONTEXT, in_setup);
    EXPECT_STATUS(SYS_E_CONTEXT, in_irq);
}

#if OS_CFG_CLOCK_EVENT
TEST_F(Time, Listing1WaitForConditionOnTheTimerWakesEvery250Ticks) {
    occurrences = 0;
    std::atomic<int> wakes{0};
    std::vector<uint32_t> event_time, system_time;
    boot([&] {
        spawn([&] {
            for (;;) {
                uint32_t t = 0;
                uint8_t size = 0;
                EXPECT_STATUS(SYS_OK, Sys_Wait_for_Condition(SYS_EVENT_1MS_TIMER, wait250times,
                                                             &t, sizeof t, &size));
                EXPECT_EQ(sizeof(uint32_t), size);
                event_time.push_back(t);
                system_time.push_back(Sys_Get_SystemTime());
                wakes++;
            }
        });
    });
    settle();
    for (int round = 1; round <= 4; round++) {
        ticks(249);
        EXPECT_EQ(round - 1, wakes.load()) << "round " << round << " woke early";
        ticks(1);
        EXPECT_EQ(round, wakes.load()) << "round " << round << " did not wake at 250";
    }
    EXPECT_EQ((std::vector<uint32_t>{250, 500, 750, 1000}), event_time);
    EXPECT_EQ(event_time, system_time);
    power_off();
}

TEST_F(Time, TimerEventDataIsTheSystemTime) {
    boot([] {
        Sys_Subscribe_to_Event(
            SYS_EVENT_1MS_TIMER, SYS_PID_SYSTEM,
            [](sys_pid, sys_event_id, const sys_event_data *d) -> bool {
                if (d->size != sizeof(uint32_t)) {
                    note("size" + std::to_string(d->size));
                } else {
                    uint32_t t;
                    std::memcpy(&t, d->value, sizeof t);
                    note(std::to_string(t) + (t == Sys_Get_SystemTime() ? "" : "!"));
                }
                return true;
            },
            nullptr);
    });
    settle();
    ticks(3);
    EXPECT_EQ("1 2 3", joined());
    advance(10);
    settle();
    uint32_t kept = 0;
    uint8_t size = 0;
    sys_status st = SYS_E_INVALID;
    irq([&] { st = Sys_Get_EventData(SYS_EVENT_1MS_TIMER, &kept, sizeof kept, &size); });
    EXPECT_STATUS(SYS_OK, st);
    EXPECT_EQ(sizeof kept, size);
    EXPECT_EQ(13u, kept);
}

TEST_F(Time, TimerEventIsNotQueuedWhileNobodyListens) {
    boot([] {});
    settle();
    ticks(300);
    EXPECT_EQ(0, stats().event_queue_peak);
    EXPECT_EQ(0, stats().event_queue_full);
    sys_status st = SYS_OK;
    irq([&] { st = Sys_Get_EventData(SYS_EVENT_1MS_TIMER, nullptr, 0, nullptr); });
    EXPECT_STATUS(SYS_E_NOT_FOUND, st) << "never dispatched";

    // A listener makes it flow; once it leaves, the kept data stops moving.
    static int heard;
    heard = 0;
    auto listener = [](sys_pid, sys_event_id, const sys_event_data *) {
        heard++;
        return true;
    };
    irq([&] { Sys_Subscribe_to_Event(SYS_EVENT_1MS_TIMER, SYS_PID_SYSTEM, listener, nullptr); });
    ticks(2);
    EXPECT_EQ(2, heard);
    irq([&] { Sys_Unsubscribe_from_Event(SYS_EVENT_1MS_TIMER, SYS_PID_SYSTEM, listener); });
    ticks(50);
    uint32_t kept = 0;
    irq([&] { st = Sys_Get_EventData(SYS_EVENT_1MS_TIMER, &kept, sizeof kept, nullptr); });
    EXPECT_STATUS(SYS_OK, st);
    EXPECT_EQ(302u, kept);
}

// Unregistering the clock event ends its subscriptions: registered again,
// it has no listener, so the tick sends it no more.
TEST_F(Time, TimerEventRegisteredAgainHasNoListenerLeft) {
    static int heard;
    heard = 0;
    sys_status reregistered = SYS_E_INVALID;
    boot([&] {
        Sys_Subscribe_to_Event(SYS_EVENT_1MS_TIMER, SYS_PID_SYSTEM,
                               [](sys_pid, sys_event_id, const sys_event_data *) {
                                   heard++;
                                   return true;
                               },
                               nullptr);
        spawn([&] {
            Sys_Sleep(5);
            Sys_Unregister_Event(SYS_EVENT_1MS_TIMER);
            reregistered = Sys_Register_Event_Sized(SYS_EVENT_1MS_TIMER, sizeof(uint32_t));
        });
    });
    settle();
    ticks(50);
    int heard_after_reregistering = heard;
    ticks(50);
    EXPECT_STATUS(SYS_OK, reregistered);
    EXPECT_GE(heard_after_reregistering, 4) << "the listener heard the clock before";
    EXPECT_EQ(heard_after_reregistering, heard) << "and nothing once it was unregistered";
    sys_status st = SYS_OK;
    irq([&] { st = Sys_Get_EventData(SYS_EVENT_1MS_TIMER, nullptr, 0, nullptr); });
    EXPECT_STATUS(SYS_E_NOT_FOUND, st) << "never sent since it was registered again";
}
#else
TEST_F(Time, WithoutTheClockEventItCannotBeRegisteredSubscribedToOrAwaited) {
    // OS_CFG_CLOCK_EVENT 0 (config.h): time goes on, but SYS_EVENT_1MS_TIMER
    // is refused at once everywhere rather than never coming.
    bool registered = true;
    sys_status reg = SYS_OK, reg_sized = SYS_OK, sub = SYS_OK, wait = SYS_OK, timed = SYS_OK;
    boot([&] {
        registered = Sys_IsEventRegistered(SYS_EVENT_1MS_TIMER);
        reg = Sys_Register_Event(SYS_EVENT_1MS_TIMER);
        reg_sized = Sys_Register_Event_Sized(SYS_EVENT_1MS_TIMER, sizeof(uint32_t));
        sub = Sys_Subscribe_to_Event(
            SYS_EVENT_1MS_TIMER, SYS_PID_SYSTEM,
            [](sys_pid, sys_event_id, const sys_event_data *) { return true; }, nullptr);
        spawn([&] {
            uint32_t t = 0;
            wait = Sys_Wait_for_Event(SYS_EVENT_1MS_TIMER, &t, sizeof t, nullptr);
            timed = Sys_Wait_for_Event_Timeout(SYS_EVENT_1MS_TIMER, 5, &t, sizeof t, nullptr);
            note("returned@" + std::to_string(Sys_Get_SystemTime()));
        });
    });
    settle();
    ticks(100);
    EXPECT_FALSE(registered);
    EXPECT_STATUS(SYS_E_INVALID, reg);
    EXPECT_STATUS(SYS_E_INVALID, reg_sized);
    EXPECT_STATUS(SYS_E_NOT_REGISTERED, sub);
    EXPECT_STATUS(SYS_E_NOT_REGISTERED, wait);
    EXPECT_STATUS(SYS_E_NOT_REGISTERED, timed);
    EXPECT_EQ("returned@0", joined()) << "at once, not after a timeout";
    EXPECT_EQ(0, stats().event_queue_peak) << "the tick queues nothing";
}
#endif

TEST_F(Time, TimeoutsAboveTwoToThe31MsDoNotEndAtTheNextTick) {
    // Distances to deadlines are taken modulo 2^32 from now, so the whole
    // 32-bit range works (deadlines compared as signed differences would
    // expire at once past 2^31 ms).
    std::atomic<bool> slept{false}, waited{false};
    sys_status sleep_status = SYS_E_INVALID, wait_status = SYS_E_INVALID;
    boot([&] {
        Sys_Register_Event(EV_A);
        spawn([&] {
            sleep_status = Sys_Sleep(UINT32_MAX);
            slept = true;
        });
        spawn([&] {
            wait_status = Sys_Wait_for_Event_Timeout(EV_A, UINT32_MAX, nullptr, 0, nullptr);
            waited = true;
        });
    });
    settle();
    ticks(3);
    EXPECT_FALSE(slept && sleep_status == SYS_OK)
        << "Sys_Sleep(UINT32_MAX) returned SYS_OK after 3 ms";
    EXPECT_FALSE(waited && wait_status == SYS_E_TIMEOUT)
        << "a UINT32_MAX ms timeout ran out after 3 ms";
}

TEST_F(Time, ANearDeadlineIsMetBesideTheFarthestOne) {
    // A UINT32_MAX ms sleep is the farthest deadline there can be; nearer
    // ones started after it still end on time, one after the other.
    boot([&] {
        spawn([] {
            Sys_Sleep(UINT32_MAX);
            note("a@" + std::to_string(Sys_Get_SystemTime()));
        });
        spawn([] {
            Sys_Sleep(3);
            note("b@" + std::to_string(Sys_Get_SystemTime()));
            Sys_Sleep(2);
            note("b@" + std::to_string(Sys_Get_SystemTime()));
        });
    });
    settle();
    ticks(8);
    EXPECT_EQ("b@3 b@5", joined());
}

// Sys_Sleep_Until: a loop whose work takes 15 ms (a sleep standing in for
// it) wakes every 100 ms on the dot, where a Sys_Sleep(100) loop drifts by
// the work's 15 ms each time; work longer than a period catches up.
TEST_F(Time, SleepUntilKeepsAPeriodWhateverTheWorkTakes) {
    std::vector<uint32_t> periodic, drifting;
    boot([&] {
        spawn([&] {
            uint32_t wake = Sys_Get_SystemTime();
            for (int k = 0; k < 4; k++) {
                EXPECT_STATUS(SYS_OK, Sys_Sleep_Until(&wake, 100));
                periodic.push_back(Sys_Get_SystemTime());
                Sys_Sleep(15);
            }
            Sys_Sleep(1000000);
        });
        spawn([&] {
            for (int k = 0; k < 4; k++) {
                Sys_Sleep(100);
                drifting.push_back(Sys_Get_SystemTime());
                Sys_Sleep(15);
            }
            Sys_Sleep(1000000);
        });
    });
    settle();
    ticks(500);
    EXPECT_EQ((std::vector<uint32_t>{100, 200, 300, 400}), periodic);
    EXPECT_EQ((std::vector<uint32_t>{100, 215, 330, 445}), drifting);
}

TEST_F(Time, SleepUntilCatchesUpAfterLongWorkAndRefusesBadCalls) {
    std::vector<uint32_t> woke;
    sys_status null_status = SYS_OK, in_setup = SYS_OK, in_setup_valid = SYS_OK;
    boot([&] {
        in_setup = Sys_Sleep_Until(nullptr, 10);
        uint32_t now = 0;
        in_setup_valid = Sys_Sleep_Until(&now, 10);
        spawn([&] {
            null_status = Sys_Sleep_Until(nullptr, 10);
            uint32_t wake = Sys_Get_SystemTime();
            Sys_Sleep(250); // work that overran two and a half periods
            for (int k = 0; k < 4; k++) {
                EXPECT_STATUS(SYS_OK, Sys_Sleep_Until(&wake, 100));
                woke.push_back(Sys_Get_SystemTime());
            }
            Sys_Sleep(1000000);
        });
    });
    settle();
    ticks(400);
    // Targets 100 and 200 have passed at 250: it returns at once for both,
    // then keeps the period: 300, 400.
    EXPECT_EQ((std::vector<uint32_t>{250, 250, 300, 400}), woke);
    EXPECT_STATUS(SYS_E_INVALID, null_status);
    EXPECT_STATUS(SYS_E_INVALID, in_setup) << "NULL is checked first";
    EXPECT_STATUS(SYS_E_CONTEXT, in_setup_valid) << "not a thread: it may not wait";
}
