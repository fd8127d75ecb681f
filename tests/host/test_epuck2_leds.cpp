// The e-puck2's own LEDs (ports/epuck/epuck2/drivers/leds.c) against a
// register model: the test applies BSRR writes to ODR as the GPIO would.
#include <gtest/gtest.h>

#include "stm32f4_register_model.hpp"

extern "C" {
#include "../../ports/epuck/epuck2/drivers/leds.h"
#include "../../ports/epuck/epuck2/drivers/stm32f4_registers.h"
}

namespace {

bool high(stm32_gpio &g, unsigned pin) {
    epuck2_model_apply_bsrr(g);
    return (g.ODR >> pin) & 1u;
}

class Leds : public ::testing::Test {
protected:
    void SetUp() override {
        epuck2_model_gpiob = {};
        epuck2_model_gpiod = {};
        epuck2_model_rcc = {};
        epuck2_model_silicon = nullptr;
        epuck2_leds_init();
    }
};

TEST_F(Leds, AllOffAtStartThePinsOutputs) {
    for (unsigned pin : {5u, 6u, 10u, 11u}) {
        EXPECT_TRUE(high(epuck2_model_gpiod, pin)) << "red ring LED on PD" << pin << " off: high";
        EXPECT_EQ(GPIO_MODE_OUTPUT, (epuck2_model_gpiod.MODER >> (2 * pin)) & 3u);
    }
    EXPECT_FALSE(high(epuck2_model_gpiob, 2)) << "body off: low";
    EXPECT_FALSE(high(epuck2_model_gpiod, 14)) << "front off: low";
    EXPECT_EQ(GPIO_MODE_OUTPUT, (epuck2_model_gpiob.MODER >> 4) & 3u);
}

TEST_F(Leds, TheRingsEvenBitsAreTheRedLedsLitLow) {
    epuck2_leds_set_ring(0x01 | 0x10 | 0x02); // LED1, LED5, and LED2 (an RGB one: not here)
    EXPECT_FALSE(high(epuck2_model_gpiod, 5)) << "LED1 lit";
    EXPECT_TRUE(high(epuck2_model_gpiod, 6)) << "LED3 off";
    EXPECT_FALSE(high(epuck2_model_gpiod, 10)) << "LED5 lit";
    EXPECT_TRUE(high(epuck2_model_gpiod, 11)) << "LED7 off";
    epuck2_leds_set_ring(0x40);
    EXPECT_TRUE(high(epuck2_model_gpiod, 5));
    EXPECT_FALSE(high(epuck2_model_gpiod, 11)) << "LED7 lit";
}

TEST_F(Leds, BodyAndFrontLitHigh) {
    epuck2_leds_set_body(true);
    epuck2_leds_set_front(true);
    EXPECT_TRUE(high(epuck2_model_gpiob, 2));
    EXPECT_TRUE(high(epuck2_model_gpiod, 14));
    epuck2_leds_set_front(false);
    EXPECT_FALSE(high(epuck2_model_gpiod, 14));
    EXPECT_TRUE(high(epuck2_model_gpiob, 2));
}

}  // namespace
