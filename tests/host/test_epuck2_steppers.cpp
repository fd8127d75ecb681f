// The e-puck2's stepper driver (ports/epuck/epuck2/drivers/steppers.c)
// against a register model: the test plays the STM32F407 - it raises the
// timers' update flags, calls the interrupt handlers, applies each BSRR
// write to ODR as the silicon does - and reads the coils the driver drove.
#include <gtest/gtest.h>

#include <set>
#include <vector>

extern "C" {
#include "../../ports/epuck/epuck2/drivers/steppers.h"
#include "../../ports/epuck/epuck2/drivers/stm32f4_registers.h"
}

namespace {

// IN1..IN4 of each motor on GPIOE (the e-puck2's board.h).
const unsigned LEFT_PINS[4] = {9, 8, 11, 10}, RIGHT_PINS[4] = {13, 12, 14, 15};

class Steppers : public ::testing::Test {
protected:
    void SetUp() override {
        epuck2_model_gpioe = {};
        epuck2_model_tim3 = {};
        epuck2_model_tim4 = {};
        epuck2_model_rcc = {};
        epuck2_steppers_init();
        apply_bsrr();
    }

    // What GPIOE does with a BSRR write: set the low half's pins, reset
    // the high half's.
    static void apply_bsrr() {
        uint32_t bsrr = epuck2_model_gpioe.BSRR;
        epuck2_model_gpioe.ODR = (epuck2_model_gpioe.ODR | (bsrr & 0xFFFF)) & ~(bsrr >> 16);
        epuck2_model_gpioe.BSRR = 0;
    }

    // A timer's update: its flag raised, its handler run.
    static void update(stm32_timer &timer, void (*handler)(void)) {
        timer.SR |= TIM_SR_UIF;
        handler();
        apply_bsrr();
        EXPECT_EQ(0u, timer.SR & TIM_SR_UIF) << "the handler clears the update flag";
    }

    // The coils of a motor as IN1..IN4 bits.
    static unsigned coils(const unsigned pins[4]) {
        unsigned c = 0;
        for (unsigned i = 0; i < 4; i++) c |= ((epuck2_model_gpioe.ODR >> pins[i]) & 1u) << i;
        return c;
    }

    static std::vector<unsigned> patterns(int updates, stm32_timer &timer, void (*handler)(void),
                                          const unsigned pins[4]) {
        std::vector<unsigned> seen;
        for (int i = 0; i < updates; i++) {
            update(timer, handler);
            seen.push_back(coils(pins));
        }
        return seen;
    }
};

TEST_F(Steppers, InitConfiguresPinsAndTimersWithTheCoilsOff) {
    for (unsigned pin : {8u, 9u, 10u, 11u, 12u, 13u, 14u, 15u})
        EXPECT_EQ(GPIO_MODE_OUTPUT, (epuck2_model_gpioe.MODER >> (2 * pin)) & 3u) << "PE" << pin;
    EXPECT_EQ(0u, epuck2_model_gpioe.ODR & 0xFF00u) << "no current held";
    for (stm32_timer *t : {&epuck2_model_tim3, &epuck2_model_tim4}) {
        EXPECT_EQ(839u, t->PSC) << "84 MHz / 840: 100 kHz";
        EXPECT_EQ(999u, t->ARR) << "stopped: 100 Hz";
        EXPECT_EQ(TIM_DIER_UIE, t->DIER);
        EXPECT_EQ(TIM_CR1_CEN | TIM_CR1_ARPE, t->CR1);
    }
    EXPECT_TRUE(epuck2_model_rcc.AHB1ENR & RCC_AHB1ENR_GPIOEEN);
    EXPECT_EQ(RCC_APB1ENR_TIM3EN | RCC_APB1ENR_TIM4EN, epuck2_model_rcc.APB1ENR);
}

TEST_F(Steppers, TheUpdateRateIsTwoHalfStepsPerStep) {
    epuck2_steppers_set(500, -250);
    EXPECT_EQ(99u, epuck2_model_tim4.ARR) << "left: 1000 half steps/s at 100 kHz";
    EXPECT_EQ(199u, epuck2_model_tim3.ARR) << "right: 500 half steps/s";
    epuck2_steppers_set(1000, 1);
    EXPECT_EQ(49u, epuck2_model_tim4.ARR);
    EXPECT_EQ(49999u, epuck2_model_tim3.ARR);
}

TEST_F(Steppers, HalfStepsGoThroughEightPatternsOneCoilAtATime) {
    epuck2_steppers_set(300, 0);
    auto seen = patterns(16, epuck2_model_tim4, TIM4_IRQHandler, LEFT_PINS);
    EXPECT_EQ(8u, std::set<unsigned>(seen.begin(), seen.end()).size());
    for (size_t i = 0; i < seen.size(); i++) {
        EXPECT_EQ(seen[i], seen[(i + 8) % seen.size()]) << "a cycle of 8";
        unsigned changed = seen[i] ^ seen[(i + 1) % seen.size()];
        EXPECT_EQ(1, __builtin_popcount(changed)) << "one coil changes per half step, at " << i;
        EXPECT_GE(__builtin_popcount(seen[i]), 1) << "a coil is always on while moving";
    }
    EXPECT_EQ(0u, coils(RIGHT_PINS)) << "the right motor stood still";
}

TEST_F(Steppers, TheMotorsFaceEachOtherSoForwardRunsThePatternsOppositeWays) {
    epuck2_steppers_set(200, 200);
    auto left = patterns(8, epuck2_model_tim4, TIM4_IRQHandler, LEFT_PINS);
    auto right = patterns(8, epuck2_model_tim3, TIM3_IRQHandler, RIGHT_PINS);
    // From the same start, after k updates the left motor is k patterns on,
    // the right one k back: the right's k-th is the left's (8 - k)-th.
    for (int k = 1; k < 8; k++) EXPECT_EQ(left[8 - k - 1], right[k - 1]) << "update " << k;
    EXPECT_EQ(left[7], right[7]) << "both back where they started";
    EXPECT_NE(left, right);
    epuck2_steppers_set(-200, 0);
    auto reversed = patterns(7, epuck2_model_tim4, TIM4_IRQHandler, LEFT_PINS);
    EXPECT_EQ(std::vector<unsigned>(left.rbegin() + 1, left.rend()), reversed)
        << "backwards retraces the same patterns";
}

TEST_F(Steppers, PositionCountsWholeStepsBothWays) {
    epuck2_steppers_set(100, -100);
    for (int i = 0; i < 10; i++) {
        update(epuck2_model_tim4, TIM4_IRQHandler);
        update(epuck2_model_tim3, TIM3_IRQHandler);
    }
    EXPECT_EQ(5, epuck2_steppers_position(0));
    EXPECT_EQ(-5, epuck2_steppers_position(1));
}

TEST_F(Steppers, StoppingReleasesTheCoilsAtTheNextUpdate) {
    epuck2_steppers_set(400, 400);
    update(epuck2_model_tim4, TIM4_IRQHandler);
    ASSERT_NE(0u, coils(LEFT_PINS));
    epuck2_steppers_set(0, 0);
    EXPECT_EQ(999u, epuck2_model_tim4.ARR);
    update(epuck2_model_tim4, TIM4_IRQHandler);
    EXPECT_EQ(0u, coils(LEFT_PINS));
    EXPECT_EQ(0, epuck2_steppers_position(0)) << "half a step is no step";
}

}  // namespace
