// The e-puck2's proximity driver (ports/epuck/epuck2/drivers/proximity.c)
// against a register model: the test plays TIM2's updates and compares, and
// ADC2's conversions, reading each channel from a model of the sensors in
// which a pulsed reading is lower only while that pair's emitters are on.
#include <gtest/gtest.h>

#include <vector>

extern "C" {
#include "../../ports/epuck/epuck2/drivers/proximity.h"
#include "../../ports/epuck/epuck2/drivers/stm32f4_registers.h"
}

namespace {

std::vector<epuck_proximity_samples> rounds;
void round_done(const epuck_proximity_samples *s) { rounds.push_back(*s); }

// Sensor s's ADC channel and its pair's emitter (the e-puck2's board.h).
const unsigned CHANNEL[8] = {12, 13, 14, 15, 9, 8, 10, 11};
struct Pin {
    stm32_gpio *port;
    unsigned pin;
};
const Pin PULSE[4] = {{&epuck2_model_gpiob, 12}, {&epuck2_model_gpiob, 14},
                      {&epuck2_model_gpioe, 2}, {&epuck2_model_gpioe, 3}};

class Proximity : public ::testing::Test {
protected:
    void SetUp() override {
        for (stm32_gpio *g : {&epuck2_model_gpiob, &epuck2_model_gpioc, &epuck2_model_gpioe}) *g = {};
        epuck2_model_tim2 = {};
        epuck2_model_adc2 = {};
        epuck2_model_adc_ccr = 0;
        epuck2_model_rcc = {};
        rounds.clear();
        epuck2_proximity_init(round_done);
        apply_bsrr();
    }

    static void apply_bsrr() {
        for (stm32_gpio *g : {&epuck2_model_gpiob, &epuck2_model_gpioe}) {
            uint32_t bsrr = g->BSRR;
            g->ODR = (g->ODR | (bsrr & 0xFFFF)) & ~(bsrr >> 16);
            g->BSRR = 0;
        }
    }

    static bool emitting(unsigned pair) { return (PULSE[pair].port->ODR >> PULSE[pair].pin) & 1u; }
    static unsigned emitters_on() {
        unsigned on = 0;
        for (unsigned p = 0; p < 4; p++) on += emitting(p);
        return on;
    }

    // A flag rises, the handler runs; SR is rc_w0: what it wrote clears
    // the bits written 0 and leaves the others as they were.
    static void timer_event(uint32_t flag) {
        uint32_t raised = epuck2_model_tim2.SR | flag;
        epuck2_model_tim2.SR = raised;
        TIM2_IRQHandler();
        epuck2_model_tim2.SR = raised & epuck2_model_tim2.SR;
        apply_bsrr();
        EXPECT_EQ(0u, epuck2_model_tim2.SR & flag) << "the handler clears its flag";
    }

    // The sensors: 3000 + s counts with the emitters off, 100 s fewer when
    // its pair's emitters shine on an obstacle.
    static uint16_t reading(unsigned sensor) {
        return (uint16_t)(emitting(sensor % 4) ? 3000 - 100 * sensor : 3000 + sensor);
    }

    // ADC2 converts the scan the driver set up: two channels, SQR3's first two.
    static void convert() {
        ASSERT_TRUE(epuck2_model_adc2.CR2 & ADC_CR2_SWSTART) << "a conversion was started";
        epuck2_model_adc2.CR2 &= ~ADC_CR2_SWSTART;
        for (unsigned i = 0; i < 2; i++) {
            unsigned channel = (epuck2_model_adc2.SQR3 >> (5 * i)) & 0x1F;
            unsigned sensor = 0;
            while (sensor < 8 && CHANNEL[sensor] != channel) sensor++;
            ASSERT_LT(sensor, 8u) << "channel " << channel << " is no sensor's";
            epuck2_model_adc2.DR = reading(sensor);
            epuck2_model_adc2.SR |= ADC_SR_EOC;
            ADC_IRQHandler();
            epuck2_model_adc2.SR &= ~ADC_SR_EOC; // reading DR clears it
        }
    }

    // The rest of a period after its update: the two compares in the order
    // their values put them (the conversion starts at compare 2, the pulse
    // ends at compare 1), the conversion done at once.
    static void compares() {
        bool sample_first = epuck2_model_tim2.CCR[1] < epuck2_model_tim2.CCR[0];
        timer_event(sample_first ? TIM_SR_CC2IF : TIM_SR_CC1IF);
        if (sample_first) convert();
        timer_event(sample_first ? TIM_SR_CC1IF : TIM_SR_CC2IF);
        if (!sample_first) convert();
        EXPECT_EQ(0u, emitters_on()) << "after compare 1 every emitter is off";
    }

    static void period() {
        timer_event(TIM_SR_UIF);
        compares();
    }
};

TEST_F(Proximity, InitSetsTheScheduleAndTheAdc) {
    const stm32_timer &t = epuck2_model_tim2;
    EXPECT_EQ(83u, t.PSC) << "84 MHz / 84: 1 MHz";
    EXPECT_EQ(1249u, t.ARR) << "1250 us: 800 Hz, a round of 8 at 100 Hz";
    EXPECT_EQ(300u, t.CCR[0]) << "the pulse";
    EXPECT_EQ(260u, t.CCR[1]) << "the sample, inside the pulse";
    EXPECT_EQ(TIM_DIER_UIE | TIM_DIER_CC1IE | TIM_DIER_CC2IE, t.DIER);
    EXPECT_TRUE(t.CR1 & TIM_CR1_CEN);
    EXPECT_EQ(ADC_CCR_ADCPRE_DIV8, epuck2_model_adc_ccr);
    EXPECT_EQ(1u, (epuck2_model_adc2.SQR1 >> 20) & 0xF) << "two conversions a scan";
    for (unsigned ch = 8; ch <= 15; ch++) {
        uint32_t smpr = ch <= 9 ? epuck2_model_adc2.SMPR2 >> (3 * ch) : epuck2_model_adc2.SMPR1 >> (3 * (ch - 10));
        EXPECT_EQ(ADC_SAMPLE_112_CYCLES, smpr & 7u) << "channel " << ch;
    }
    for (unsigned pin = 0; pin <= 5; pin++)
        EXPECT_EQ(GPIO_MODE_ANALOG, (epuck2_model_gpioc.MODER >> (2 * pin)) & 3u) << "PC" << pin;
    EXPECT_EQ(0xFu, epuck2_model_gpiob.MODER & 0xFu) << "PB0, PB1 analog";
    EXPECT_EQ(0u, emitters_on());
}

TEST_F(Proximity, ARoundSamplesEachPairWithoutAndWithItsPulse) {
    for (int p = 0; p < 8; p++) {
        timer_event(TIM_SR_UIF);
        unsigned pair = (unsigned)p / 2;
        EXPECT_EQ(p % 2 == 1, emitting(pair)) << "period " << p;
        EXPECT_LE(emitters_on(), 1u) << "one pair at a time";
        compares();
        EXPECT_EQ(CHANNEL[pair] | (CHANNEL[pair + 4] << 5), epuck2_model_adc2.SQR3) << "period " << p;
        EXPECT_EQ(p == 7 ? 1u : 0u, rounds.size()) << "after period " << p;
    }
    ASSERT_EQ(1u, rounds.size());
    for (unsigned s = 0; s < 8; s++) {
        EXPECT_EQ(3000 + s, rounds[0].off[s]) << "sensor " << s;
        EXPECT_EQ(3000 - 100 * s, rounds[0].pulsed[s]) << "sensor " << s << ", sampled inside its pulse";
    }
}

TEST_F(Proximity, RoundsFollowOneAnotherEveryEightPeriods) {
    for (int p = 0; p < 24; p++) period();
    EXPECT_EQ(3u, rounds.size());
    EXPECT_EQ(3007, rounds[2].off[7]);
}

}  // namespace
