// The e-puck2's link to its ESP32 (ports/epuck/epuck2/drivers/esp32_link.c)
// against a register model: the test plays SPI1, taking each byte written
// to DR and noting whether the ESP32's chip select (PA15) was low then.
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

void apply_bsrr(stm32_gpio &g) {
    uint32_t bsrr = g.BSRR;
    g.ODR = (g.ODR | (bsrr & 0xFFFF)) & ~(bsrr >> 16);
    g.BSRR = 0;
}
bool selected() { return (epuck2_model_gpioa.ODR & (1u << CS)) == 0; }

// A byte in DR goes out at once, the ESP32's comes back: TXE and RXNE set.
void spi_silicon() {
    apply_bsrr(epuck2_model_gpioa);
    if (spi_mute) return;
    if (epuck2_model_spi1.DR != TAKEN) {
        sent.push_back({(uint8_t)epuck2_model_spi1.DR, selected()});
        epuck2_model_spi1.DR = TAKEN;
        epuck2_model_spi1.SR = SPI_SR_TXE | SPI_SR_RXNE;
    }
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
        sent.clear();
        spi_mute = false;
        epuck2_model_polls = 0;
        epuck2_model_silicon = spi_silicon;
        epuck2_esp32_link_init();
        apply_bsrr(epuck2_model_gpioa);
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
    apply_bsrr(epuck2_model_gpioa);
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
    apply_bsrr(epuck2_model_gpioa);
    EXPECT_TRUE(sent.empty());
    EXPECT_FALSE(selected());
}

}  // namespace
