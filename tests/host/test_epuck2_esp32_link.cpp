// The e-puck2's link to its ESP32 (ports/epuck/epuck2/drivers/esp32_link.c)
// against a register model: the test plays SPI1, taking each byte written
// to DR and noting whether the ESP32's chip select (PA15) was low then, and
// TIM6 counting microseconds for the pause after each exchange.
#include <gtest/gtest.h>

#include <vector>

#include "stm32f4_register_model.hpp"

extern "C" {
#include "../../ports/epuck/epuck2/drivers/esp32_link.h"
#include "../../ports/epuck/epuck2/drivers/stm32f4_registers.h"
#include "openswarm/epuck.h"
}

namespace {

constexpr uint32_t TAKEN = 0xFFFFFFFFu;
constexpr unsigned CS = 15;

struct Sent {
    uint8_t byte;
    bool selected;
};
std::vector<Sent> sent;
bool spi_mute;
uint64_t now_us;                      // the test's clock
std::vector<uint64_t> exchange_start; // when each packet's first byte went

bool selected() { return (epuck2_model_gpioa.ODR & (1u << CS)) == 0; }

// A byte in DR goes out at once, the ESP32's comes back: TXE and RXNE set.
void spi_silicon() {
    epuck2_model_apply_bsrr(epuck2_model_gpioa);
    if (spi_mute) return;
    if (epuck2_model_spi1.DR != TAKEN) {
        if (sent.size() % EPUCK2_ESP32_PACKET_BYTES == 0) exchange_start.push_back(now_us);
        sent.push_back({(uint8_t)epuck2_model_spi1.DR, selected()});
        epuck2_model_spi1.DR = TAKEN;
        epuck2_model_spi1.SR = SPI_SR_TXE | SPI_SR_RXNE;
    }
}

// TIM6 (RM0090 20.4): counts at APB1's timer clock / (PSC + 1); past ARR
// an update: UIF, the counter stopped in one-pulse mode; the interrupt
// runs whenever UIE and UIF are both set.
void tim6_interrupts() {
    stm32_timer &t = epuck2_model_tim6;
    for (int guard = 0; guard < 10 && (t.DIER & TIM_DIER_UIE) && (t.SR & TIM_SR_UIF); guard++)
        TIM6_DAC_IRQHandler();
}
void elapse_us(uint64_t us) {
    stm32_timer &t = epuck2_model_tim6;
    const uint32_t ticks_per_us = 84u / (t.PSC + 1u);
    ASSERT_EQ(1u, ticks_per_us) << "TIM6 at 1 MHz";
    for (uint64_t i = 0; i < us; i++) {
        now_us++;
        if (t.CR1 & TIM_CR1_CEN) {
            if (++t.CNT > t.ARR) {
                t.CNT = 0;
                t.SR |= TIM_SR_UIF;
                if (t.CR1 & TIM_CR1_OPM) t.CR1 &= ~TIM_CR1_CEN;
            }
        }
        tim6_interrupts();
    }
}

// The colours of the packets sent, in order (the first byte of each is
// LED2's red, enough to tell the test's colours apart).
std::vector<uint8_t> reds_sent() {
    std::vector<uint8_t> reds;
    for (size_t i = 0; i < sent.size(); i += EPUCK2_ESP32_PACKET_BYTES) reds.push_back(sent[i].byte);
    return reds;
}

std::vector<uint8_t> last_packet() {
    std::vector<uint8_t> bytes;
    for (size_t i = sent.size() - EPUCK2_ESP32_PACKET_BYTES; i < sent.size(); i++) bytes.push_back(sent[i].byte);
    return bytes;
}

std::vector<uint8_t> packet(uint8_t rgb) {
    std::vector<uint8_t> p(EPUCK2_ESP32_PACKET_BYTES);
    epuck2_esp32_rgb_packet(rgb, p.data());
    return p;
}
std::vector<uint8_t> four_times(uint8_t r, uint8_t g, uint8_t b) {
    return {r, g, b, r, g, b, r, g, b, r, g, b};
}

class Esp32Link : public ::testing::Test {
protected:
    void SetUp() override {
        epuck2_model_gpioa = {};
        epuck2_model_gpiob = {};
        epuck2_model_spi1 = {};
        epuck2_model_spi1.DR = TAKEN;
        epuck2_model_spi1.SR = SPI_SR_TXE;
        epuck2_model_rcc = {};
        epuck2_model_tim6 = {};
        sent.clear();
        exchange_start.clear();
        now_us = 0;
        spi_mute = false;
        epuck2_model_polls = 0;
        epuck2_model_silicon = spi_silicon;
        epuck2_esp32_link_init();
        epuck2_model_apply_bsrr(epuck2_model_gpioa);
    }
    void TearDown() override { epuck2_model_silicon = nullptr; }
};

TEST_F(Esp32Link, EachLedGetsRedGreenBlueInPercent) {
    EXPECT_EQ(four_times(0, 0, 0), packet(EPUCK_RGB(0, 0, 0)));
    EXPECT_EQ(four_times(100, 0, 0), packet(EPUCK_RGB(3, 0, 0)));
    EXPECT_EQ(four_times(0, 100, 0), packet(EPUCK_RGB(0, 3, 0)));
    EXPECT_EQ(four_times(0, 0, 100), packet(EPUCK_RGB(0, 0, 3)));
    EXPECT_EQ(four_times(33, 66, 100), packet(EPUCK_RGB(1, 2, 3)));
    EXPECT_EQ(four_times(66, 33, 0), packet(EPUCK_RGB(2, 1, 0)));
}

TEST_F(Esp32Link, NoByteReachesTheRangeThatMeansLeaveAlone) {
    // The ESP32 leaves an LED as it is for a value over 100 (the firmware
    // sends 101 for that), so every level of every colour stays within 0..100.
    for (unsigned rgb = 0; rgb < 64; rgb++)
        for (uint8_t b : packet((uint8_t)rgb)) EXPECT_LE(b, 100) << "rgb " << rgb;
}

TEST_F(Esp32Link, Spi1IsAMode0MasterAt10_5MHz) {
    const stm32_spi &s = epuck2_model_spi1;
    EXPECT_TRUE(s.CR1 & SPI_CR1_MSTR);
    EXPECT_EQ(84000000u >> (((s.CR1 >> 3) & 7u) + 1), 10500000u) << "APB2 / 8";
    EXPECT_EQ(0u, s.CR1 & 3u) << "CPOL = CPHA = 0";
    EXPECT_EQ(0u, s.CR1 & ((1u << 7) | (1u << 11))) << "MSB first, 8 bits";
    EXPECT_EQ(SPI_CR1_SSM | SPI_CR1_SSI, s.CR1 & (SPI_CR1_SSM | SPI_CR1_SSI)) << "chip select by software";
    EXPECT_TRUE(s.CR1 & SPI_CR1_SPE);
    EXPECT_EQ(GPIO_MODE_OUTPUT, (epuck2_model_gpioa.MODER >> (2 * CS)) & 3u);
    EXPECT_FALSE(selected()) << "the ESP32 deselected until a packet";
    EXPECT_EQ(5u, (epuck2_model_gpioa.AFR[0] >> (4 * 7)) & 0xFu) << "PA7 MOSI AF5";
    EXPECT_EQ(5u, (epuck2_model_gpiob.AFR[0] >> (4 * 3)) & 0xFu) << "PB3 SCK AF5";
    EXPECT_EQ(5u, (epuck2_model_gpiob.AFR[0] >> (4 * 4)) & 0xFu) << "PB4 MISO AF5";
}

TEST_F(Esp32Link, SettingTheLedsSendsThePacketWithTheEsp32Selected) {
    EXPECT_TRUE(epuck2_esp32_set_rgb_leds(EPUCK_RGB(1, 2, 3)));
    epuck2_model_apply_bsrr(epuck2_model_gpioa);
    ASSERT_EQ(EPUCK2_ESP32_PACKET_BYTES, sent.size());
    std::vector<uint8_t> bytes;
    for (const Sent &s : sent) {
        bytes.push_back(s.byte);
        EXPECT_TRUE(s.selected) << "byte " << bytes.size() - 1;
    }
    EXPECT_EQ(four_times(33, 66, 100), bytes);
    EXPECT_FALSE(selected()) << "deselected after";
}

TEST_F(Esp32Link, ASilentSpiFailsInTimeAndDeselects) {
    spi_mute = true;
    epuck2_model_spi1.SR = 0; // never ready
    EXPECT_FALSE(epuck2_esp32_set_rgb_leds(EPUCK_RGB(3, 3, 3)));
    EXPECT_LT(epuck2_model_polls, 1000000u);
    epuck2_model_apply_bsrr(epuck2_model_gpioa);
    EXPECT_TRUE(sent.empty());
    EXPECT_FALSE(selected());
}

TEST_F(Esp32Link, ThePauseIsTim6OnePulseOf500Microseconds) {
    const stm32_timer &t = epuck2_model_tim6;
    EXPECT_TRUE(epuck2_model_rcc.APB1ENR & RCC_APB1ENR_TIM6EN);
    EXPECT_EQ(1000000u, 84000000u / (t.PSC + 1u)) << "1 MHz from APB1's 84 MHz timer clock";
    uint32_t pause_us = t.ARR + 1u;
    EXPECT_GE(pause_us, 350u) << "GCtronic's firmware pauses 350-500 us";
    EXPECT_LE(pause_us, 500u);
    EXPECT_TRUE(t.DIER & TIM_DIER_UIE);
    EXPECT_FALSE(t.CR1 & TIM_CR1_CEN) << "no pause before the first exchange";
    EXPECT_TRUE(epuck2_esp32_set_rgb_leds(EPUCK_RGB(3, 0, 0)));
    EXPECT_TRUE(t.CR1 & TIM_CR1_OPM);
    EXPECT_TRUE(t.CR1 & TIM_CR1_CEN) << "the pause starts with the exchange";
}

TEST_F(Esp32Link, ACommandDuringThePauseWaitsForItsEnd) {
    epuck2_esp32_set_rgb_leds(EPUCK_RGB(3, 0, 0));
    elapse_us(100);
    epuck2_esp32_set_rgb_leds(EPUCK_RGB(1, 0, 0));
    EXPECT_EQ((std::vector<uint8_t>{100}), reds_sent()) << "not sent inside the pause";
    elapse_us(600);
    EXPECT_EQ((std::vector<uint8_t>{100, 33}), reds_sent()) << "sent when the pause ended, not lost";
    ASSERT_EQ(2u, exchange_start.size());
    EXPECT_GE(exchange_start[1] - exchange_start[0], 350u);
}

TEST_F(Esp32Link, TheLatestColourWinsAndExchangesStayAPauseApart) {
    epuck2_esp32_set_rgb_leds(EPUCK_RGB(3, 0, 0));
    elapse_us(50);
    epuck2_esp32_set_rgb_leds(EPUCK_RGB(1, 0, 0));
    elapse_us(50);
    epuck2_esp32_set_rgb_leds(EPUCK_RGB(2, 0, 0));
    elapse_us(50);
    epuck2_esp32_set_rgb_leds(EPUCK_RGB(0, 0, 0)); // the latest
    elapse_us(2000);
    EXPECT_EQ((std::vector<uint8_t>{100, 0}), reds_sent());
    // A burst: a command every 100 us for 5 ms; the exchanges at most one a
    // pause, and the last command's colour the last one sent.
    for (int i = 0; i < 50; i++) {
        epuck2_esp32_set_rgb_leds(EPUCK_RGB(i % 4, 0, 0));
        elapse_us(100);
    }
    epuck2_esp32_set_rgb_leds(EPUCK_RGB(3, 3, 3));
    elapse_us(2000);
    for (size_t i = 1; i < exchange_start.size(); i++)
        EXPECT_GE(exchange_start[i] - exchange_start[i - 1], 350u) << "exchange " << i;
    ASSERT_FALSE(sent.empty());
    EXPECT_EQ(four_times(100, 100, 100), last_packet()) << "the latest colour is what the LEDs end with";
    EXPECT_FALSE(epuck2_model_tim6.CR1 & TIM_CR1_CEN) << "idle once nothing is kept";
}

TEST_F(Esp32Link, ACommandAfterThePauseGoesOutAtOnce) {
    epuck2_esp32_set_rgb_leds(EPUCK_RGB(3, 0, 0));
    elapse_us(501);
    epuck2_esp32_set_rgb_leds(EPUCK_RGB(1, 0, 0));
    EXPECT_EQ((std::vector<uint8_t>{100, 33}), reds_sent());
    EXPECT_EQ(501u, exchange_start[1] - exchange_start[0]);
}

TEST_F(Esp32Link, APauseEndingWhileACommandIsKeptIsNotMissed) {
    epuck2_esp32_set_rgb_leds(EPUCK_RGB(3, 0, 0));
    // The pause ends with the interrupt held off (the thread side is
    // deciding): the update flag waits, and is taken once it lets go.
    epuck2_model_tim6.DIER = 0;
    elapse_us(600);
    epuck2_model_tim6.DIER = TIM_DIER_UIE;
    epuck2_esp32_set_rgb_leds(EPUCK_RGB(2, 0, 0));
    tim6_interrupts();
    EXPECT_EQ((std::vector<uint8_t>{100, 66}), reds_sent());
}

TEST_F(Esp32Link, AnInterruptTakenLateWhileTheThreadHoldsItOffDoesNothing) {
    epuck2_esp32_set_rgb_leds(EPUCK_RGB(3, 0, 0));
    epuck2_esp32_set_rgb_leds(EPUCK_RGB(1, 0, 0)); // kept
    // The thread side holds the interrupt off (UIE clear) when the pause
    // ends; an interrupt the NVIC had pended before runs now: it must
    // leave the pause's end to be taken when the thread lets go.
    epuck2_model_tim6.DIER = 0;
    elapse_us(600);
    TIM6_DAC_IRQHandler();
    EXPECT_EQ((std::vector<uint8_t>{100}), reds_sent());
    EXPECT_TRUE(epuck2_model_tim6.SR & TIM_SR_UIF) << "the end still to be taken";
    epuck2_model_tim6.DIER = TIM_DIER_UIE;
    tim6_interrupts();
    EXPECT_EQ((std::vector<uint8_t>{100, 33}), reds_sent());
}

TEST_F(Esp32Link, AFailedExchangeAtThePausesEndIsCounted) {
    epuck2_esp32_set_rgb_leds(EPUCK_RGB(3, 0, 0));
    epuck2_esp32_set_rgb_leds(EPUCK_RGB(1, 0, 0)); // kept
    spi_mute = true;
    epuck2_model_spi1.SR = 0;
    elapse_us(600);
    EXPECT_EQ(1u, epuck2_esp32_failed_exchanges());
}

}  // namespace
