// The e-puck2's selector (ports/epuck/epuck2/drivers/selector.c) against a
// register model: the test sets the four pins' input levels (PC13, PC14,
// PC15, PD4) among others on the same ports, raises TIM7's update and reads
// what the handler reports.
#include <gtest/gtest.h>

#include <vector>

extern "C" {
#include "../../ports/epuck/epuck2/drivers/selector.h"
#include "../../ports/epuck/epuck2/drivers/stm32f4_registers.h"
}

namespace {

std::vector<uint8_t> reads;
void on_read(uint8_t position) { reads.push_back(position); }

// The switch at a position, with every other pin of both ports at `others`.
void turn_to(unsigned position, bool others) {
    uint32_t c = others ? 0xFFFFu & ~(7u << 13) : 0;
    uint32_t d = others ? 0xFFFFu & ~(1u << 4) : 0;
    epuck2_model_gpioc.IDR = c | (position & 7u) << 13;
    epuck2_model_gpiod.IDR = d | ((position >> 3) & 1u) << 4;
}

void update() {
    epuck2_model_tim7.SR |= TIM_SR_UIF;
    TIM7_IRQHandler();
    EXPECT_EQ(0u, epuck2_model_tim7.SR & TIM_SR_UIF) << "the handler clears its flag";
}

class Selector : public ::testing::Test {
protected:
    void SetUp() override {
        epuck2_model_gpioc = {};
        epuck2_model_gpiod = {};
        epuck2_model_gpioc.MODER = 0xFFFFFFFFu; // analog, as after other set-ups
        epuck2_model_tim7 = {};
        epuck2_model_rcc = {};
        reads.clear();
        epuck2_selector_init(on_read);
    }
};

TEST_F(Selector, PinsArePulledDownInputsAndTim7Updates20TimesASecond) {
    for (unsigned pin = 13; pin <= 15; pin++) {
        EXPECT_EQ(GPIO_MODE_INPUT, (epuck2_model_gpioc.MODER >> (2 * pin)) & 3u) << "PC" << pin;
        EXPECT_EQ(GPIO_PULL_DOWN, (epuck2_model_gpioc.PUPDR >> (2 * pin)) & 3u) << "PC" << pin;
    }
    EXPECT_EQ(GPIO_MODE_INPUT, (epuck2_model_gpiod.MODER >> 8) & 3u) << "PD4";
    EXPECT_EQ(GPIO_PULL_DOWN, (epuck2_model_gpiod.PUPDR >> 8) & 3u) << "PD4";
    EXPECT_EQ(0x3u, epuck2_model_gpioc.MODER & 0x3u) << "PC0 left as it was";
    const stm32_timer &t = epuck2_model_tim7;
    EXPECT_EQ(20u, 84000000u / ((t.PSC + 1) * (t.ARR + 1)));
    EXPECT_EQ(TIM_DIER_UIE, t.DIER);
    EXPECT_TRUE(t.CR1 & TIM_CR1_CEN);
    EXPECT_TRUE(epuck2_model_rcc.APB1ENR & RCC_APB1ENR_TIM7EN);
}

TEST_F(Selector, EachPositionReadsAsItsFourPins) {
    for (bool others : {false, true})
        for (unsigned p = 0; p < 16; p++) {
            turn_to(p, others);
            update();
            ASSERT_FALSE(reads.empty());
            EXPECT_EQ(p, reads.back()) << "other pins " << (others ? "high" : "low");
            EXPECT_EQ(p, epuck2_selector_position());
        }
    EXPECT_EQ(32u, reads.size()) << "a read every update";
}

TEST_F(Selector, PinsHighMeanOnesNoInversion) {
    epuck2_model_gpiod.IDR = 1u << 4;
    EXPECT_EQ(8u, epuck2_selector_position()) << "PD4 alone: bit 3";
    epuck2_model_gpiod.IDR = 0;
    epuck2_model_gpioc.IDR = 1u << 13;
    EXPECT_EQ(1u, epuck2_selector_position()) << "PC13 alone: bit 0";
    epuck2_model_gpioc.IDR = 1u << 15;
    EXPECT_EQ(4u, epuck2_selector_position()) << "PC15 alone: bit 2";
    epuck2_model_gpioc.IDR = 0;
    EXPECT_EQ(0u, epuck2_selector_position()) << "all low: position 0";
}

}  // namespace
