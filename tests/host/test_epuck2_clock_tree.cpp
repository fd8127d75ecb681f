// The e-puck2's clock tree (ports/epuck/epuck2/drivers/clock_tree.c)
// against a register model: the test plays RCC, turning each clock on some
// waits after it is asked for (or never), and checks at every wait that
// nothing was done before its time.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "stm32f4_register_model.hpp"

extern "C" {
#include "../../ports/epuck/epuck2/drivers/clock_tree.h"
#include "../../ports/epuck/epuck2/drivers/stm32f4_registers.h"
}

namespace {

constexpr uint64_t NEVER = ~0ull;

struct Rcc {
    uint64_t hse_after = 30, pll_after = 50, switch_after = 5; // polls after being asked
    uint64_t hse_asked = NEVER, pll_asked = NEVER, switch_asked = NEVER;
    std::vector<std::string> misdeeds; // what the driver did before its time
    std::vector<std::string> seen;     // the steps in the order the model saw them
} rcc;

void saw(const std::string &step) {
    if (rcc.seen.empty() || rcc.seen.back() != step) rcc.seen.push_back(step);
}

bool ready(uint64_t asked, uint64_t after) { return asked != NEVER && after != NEVER && epuck2_model_polls - asked >= after; }

void rcc_silicon() {
    stm32_rcc_clocks &r = epuck2_model_rcc_clocks;
    uint64_t now = epuck2_model_polls;
    if ((r.CR & RCC_CR_HSEON) && rcc.hse_asked == NEVER) {
        rcc.hse_asked = now;
        saw("HSE on");
        if (!(r.CR & RCC_CR_HSEBYP)) rcc.misdeeds.push_back("HSE on without bypass (the e-puck2's HSE is an oscillator)");
        if (!(epuck2_model_pwr_cr & PWR_CR_VOS_SCALE1)) rcc.misdeeds.push_back("HSE before voltage scale 1");
    }
    if ((r.CR & RCC_CR_PLLON) && rcc.pll_asked == NEVER) {
        rcc.pll_asked = now;
        saw("PLL on");
        if (!(r.CR & RCC_CR_HSERDY)) rcc.misdeeds.push_back("PLL on before HSE ready");
        if (r.PLLCFGR == 0) rcc.misdeeds.push_back("PLL on before it was configured");
    }
    if ((r.CFGR & RCC_CFGR_SW_MASK) == RCC_CFGR_SW_PLL && rcc.switch_asked == NEVER) {
        rcc.switch_asked = now;
        saw("switch to PLL");
        if (!(r.CR & RCC_CR_PLLRDY)) rcc.misdeeds.push_back("switch before the PLL locked");
        if ((epuck2_model_flash_acr & FLASH_ACR_LATENCY_MASK) != 5) rcc.misdeeds.push_back("switch before 5 wait states");
        if ((r.CFGR & (0x7u << 10)) != RCC_CFGR_PPRE1_DIV4) rcc.misdeeds.push_back("switch before APB1 /4");
    }
    if (ready(rcc.hse_asked, rcc.hse_after)) r.CR |= RCC_CR_HSERDY;
    if (ready(rcc.pll_asked, rcc.pll_after)) r.CR |= RCC_CR_PLLRDY;
    if (ready(rcc.switch_asked, rcc.switch_after) && (r.CFGR & RCC_CFGR_SW_MASK) == RCC_CFGR_SW_PLL)
        r.CFGR = (r.CFGR & ~RCC_CFGR_SWS_MASK) | RCC_CFGR_SWS_PLL;
}

class ClockTree : public ::testing::Test {
protected:
    void SetUp() override {
        epuck2_model_rcc_clocks = {};
        epuck2_model_rcc = {};
        epuck2_model_flash_acr = 0;
        epuck2_model_pwr_cr = 0;
        rcc = Rcc{};
        epuck2_model_polls = 0;
        epuck2_model_silicon = rcc_silicon;
    }
    void TearDown() override { epuck2_model_silicon = nullptr; }
};

TEST_F(ClockTree, RunsTheCoreAt168MHzFromThe24MHzOscillator) {
    ASSERT_EQ(EPUCK2_CLOCKS_RUNNING, epuck2_clock_tree_start());
    const stm32_rcc_clocks &r = epuck2_model_rcc_clocks;
    uint32_t m = r.PLLCFGR & 0x3Fu, n = (r.PLLCFGR >> 6) & 0x1FFu, p = 2u * (((r.PLLCFGR >> 16) & 3u) + 1u),
             q = (r.PLLCFGR >> 24) & 0xFu;
    EXPECT_TRUE(r.PLLCFGR & RCC_PLLCFGR_PLLSRC_HSE);
    EXPECT_EQ(1000000u, EPUCK2_HSE_HZ / m) << "VCO input";
    EXPECT_EQ(168000000u, EPUCK2_HSE_HZ / m * n / p) << "core";
    EXPECT_EQ(48000000u, EPUCK2_HSE_HZ / m * n / q) << "USB";
    EXPECT_EQ(0u, (r.CFGR >> 4) & 0xFu) << "AHB undivided";
    EXPECT_EQ(RCC_CFGR_PPRE1_DIV4 | RCC_CFGR_PPRE2_DIV2, r.CFGR & ((7u << 10) | (7u << 13))) << "APB1 42, APB2 84 MHz";
    EXPECT_EQ(168000000u / 4u, (uint32_t)EPUCK2_APB1_HZ);
    EXPECT_EQ(5u, epuck2_model_flash_acr & FLASH_ACR_LATENCY_MASK);
    EXPECT_TRUE(epuck2_model_flash_acr & FLASH_ACR_PRFTEN);
    EXPECT_TRUE(epuck2_model_rcc.APB1ENR & RCC_APB1ENR_PWREN);
}

TEST_F(ClockTree, StepsInOrderEachAfterTheLastIsReady) {
    ASSERT_EQ(EPUCK2_CLOCKS_RUNNING, epuck2_clock_tree_start());
    EXPECT_EQ((std::vector<std::string>{"HSE on", "PLL on", "switch to PLL"}), rcc.seen);
    EXPECT_TRUE(rcc.misdeeds.empty()) << rcc.misdeeds.front();
    // It waited: each step came only once the clock before it was ready.
    EXPECT_GE(rcc.pll_asked - rcc.hse_asked, rcc.hse_after);
    EXPECT_GE(rcc.switch_asked - rcc.pll_asked, rcc.pll_after);
    EXPECT_GE(epuck2_model_polls - rcc.switch_asked, rcc.switch_after);
}

TEST_F(ClockTree, AnHseThatNeverStartsIsReportedInBoundedTime) {
    rcc.hse_after = NEVER;
    EXPECT_EQ(EPUCK2_CLOCKS_NO_HSE, epuck2_clock_tree_start());
    EXPECT_LE(epuck2_model_polls, (uint64_t)EPUCK2_CLOCK_WAIT_POLLS);
    EXPECT_EQ(NEVER, rcc.pll_asked) << "no PLL without its source";
    EXPECT_EQ(0u, epuck2_model_rcc_clocks.CFGR) << "left on the internal clock, buses undivided";
    EXPECT_NE(std::string::npos, std::string(epuck2_clock_status_text(EPUCK2_CLOCKS_NO_HSE)).find("HSE"));
}

TEST_F(ClockTree, APllThatNeverLocksIsReported) {
    rcc.pll_after = NEVER;
    EXPECT_EQ(EPUCK2_CLOCKS_NO_PLL, epuck2_clock_tree_start());
    EXPECT_EQ(NEVER, rcc.switch_asked) << "never switched to an unlocked PLL";
    EXPECT_EQ(0u, epuck2_model_rcc_clocks.CFGR);
    EXPECT_LE(epuck2_model_polls, 2u * EPUCK2_CLOCK_WAIT_POLLS);
}

TEST_F(ClockTree, ASwitchThatNeverHappensIsReportedAndUndone) {
    rcc.switch_after = NEVER;
    EXPECT_EQ(EPUCK2_CLOCKS_NO_SWITCH, epuck2_clock_tree_start());
    EXPECT_EQ(0u, epuck2_model_rcc_clocks.CFGR & (RCC_CFGR_SW_MASK | (7u << 10) | (7u << 13)))
        << "back to the internal clock with undivided buses";
    EXPECT_STREQ("the core never switched to the PLL", epuck2_clock_status_text(EPUCK2_CLOCKS_NO_SWITCH));
}

}  // namespace
