// The dsPIC e-puck's two steppers on one timer (ports/epuck/dspic/src/
// step_schedule.c) against a model of Timer3: period-match mode, the
// period set to the nearer step at each interrupt, stopped and restarted
// when a speed changes. Every step of each motor is timed in counts.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

extern "C" {
#include "step_schedule.h"
}

namespace {

struct Timer3 {
    step_schedule schedule{};
    uint32_t now = 0;        // counts since the start
    uint32_t last_match = 0; // when the timer last matched or restarted
    uint16_t period = 0;     // counts from last_match to the next match; 0: stopped
    std::vector<uint32_t> steps[STEP_MOTORS];

    void run_to(uint32_t t) {
        while (period != 0 && last_match + period <= t) {
            last_match += period;
            uint16_t next = 0;
            uint8_t stepping = step_schedule_tick(&schedule, period, &next);
            for (unsigned m = 0; m < STEP_MOTORS; m++)
                if (stepping & (1u << m)) steps[m].push_back(last_match);
            period = next;
        }
        now = t;
    }
    // As board_steppers.c: the timer stopped, TMR3 read, the timer restarted.
    void set(uint8_t motor, uint16_t step_period) {
        uint16_t position = period != 0 ? (uint16_t)(now - last_match) : 0;
        period = step_schedule_set(&schedule, motor, step_period, position);
        last_match = now;
    }
};

std::vector<uint32_t> gaps(const std::vector<uint32_t> &times) {
    std::vector<uint32_t> out;
    for (size_t i = 1; i < times.size(); i++) out.push_back(times[i] - times[i - 1]);
    return out;
}

void expect_every(const std::vector<uint32_t> &times, uint32_t gap, const char *what) {
    for (uint32_t g : gaps(times)) ASSERT_EQ(gap, g) << what;
}

} // namespace

TEST(DspicSteps, EachMotorKeepsItsOwnPeriodOnOneTimer) {
    Timer3 t;
    t.set(0, 58);  // 1000 steps/s at 57600 counts/s
    t.set(1, 115); // 500 steps/s
    t.run_to(57600);
    EXPECT_EQ(57600u / 58u, t.steps[0].size());
    EXPECT_EQ(57600u / 115u, t.steps[1].size());
    EXPECT_EQ(58u, t.steps[0].front());
    expect_every(t.steps[0], 58, "left");
    expect_every(t.steps[1], 115, "right");
}

TEST(DspicSteps, ChangingOneSpeedLeavesTheOtherInStep) {
    Timer3 t;
    t.set(0, 100);
    t.set(1, 300);
    t.run_to(1030); // between two of the left's steps, inside the right's
    t.set(1, 70);
    t.run_to(5000);
    expect_every(t.steps[0], 100, "left, across the right's change");
    ASSERT_FALSE(t.steps[1].empty());
    EXPECT_EQ(900u, t.steps[1][2]) << "the right's last step before the change";
    EXPECT_EQ(1030u + 70u, t.steps[1][3]) << "its first step a whole new period after the change";
    std::vector<uint32_t> after(t.steps[1].begin() + 3, t.steps[1].end());
    expect_every(after, 70, "right, after the change");
}

TEST(DspicSteps, EqualPeriodsStepTogether) {
    Timer3 t;
    t.set(0, 58);
    t.set(1, 58);
    t.run_to(580);
    EXPECT_EQ(t.steps[0], t.steps[1]);
    EXPECT_EQ(10u, t.steps[0].size());
}

TEST(DspicSteps, StoppingOneKeepsTheOtherAndBothStopTheTimer) {
    Timer3 t;
    t.set(0, 50);
    t.set(1, 80);
    t.run_to(400);
    t.set(1, 0);
    size_t right = t.steps[1].size();
    t.run_to(1000);
    EXPECT_EQ(right, t.steps[1].size()) << "a stopped motor does not step";
    expect_every(t.steps[0], 50, "left goes on");
    EXPECT_EQ(20u, t.steps[0].size());
    t.set(0, 0);
    EXPECT_EQ(0u, t.period) << "no motor runs: the timer stays off";
    t.run_to(5000);
    EXPECT_EQ(20u, t.steps[0].size());
}

TEST(DspicSteps, AStepDueWhenTheTimerStopsIsNotLost) {
    Timer3 t;
    t.set(0, 100);
    t.set(1, 40);
    t.run_to(80);  // the right stepped at 40 and 80; the left is due at 100
    t.now = 100;   // the timer stopped at the left's step, before its interrupt ran
    t.set(1, 40);
    t.run_to(101);
    ASSERT_EQ(1u, t.steps[0].size());
    EXPECT_EQ(101u, t.steps[0][0]) << "it comes at the next count";
}

TEST(DspicSteps, TheSlowestSpeedFitsTheTimer) {
    Timer3 t;
    t.set(0, 57600); // 1 step/s
    t.run_to(3 * 57600);
    ASSERT_EQ(3u, t.steps[0].size());
    expect_every(t.steps[0], 57600, "1 step/s");
}
