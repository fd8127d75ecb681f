// The e-puck2's console (ports/epuck/epuck2/drivers/console_usart.c)
// against a register model: the test plays USART3 (a byte written to DR is
// on the line; TXE comes back when the test says the byte went out) and
// the NVIC (the TXE interrupt runs while TXEIE and TXE are both set).
#include <gtest/gtest.h>

#include <string>

#include "stm32f4_register_model.hpp"

extern "C" {
#include "../../ports/epuck/epuck2/drivers/console_usart.h"
#include "../../ports/epuck/epuck2/drivers/stm32f4_registers.h"
}

namespace {

constexpr uint32_t TAKEN = 0xFFFFFFFFu;
std::string line;    // what went out on TX
bool transmitter_dead; // TXE never comes back

// The shift register takes DR's byte at once: TXE again (unless dead).
void usart_silicon() {
    stm32_usart &u = epuck2_model_usart3;
    if (u.DR != TAKEN) {
        line += (char)u.DR;
        u.DR = TAKEN;
        u.SR &= ~USART_SR_TXE;
    }
    if (!transmitter_dead) u.SR |= USART_SR_TXE;
}

// The interrupts the hardware would raise, until it has none to raise.
void run_interrupts() {
    stm32_usart &u = epuck2_model_usart3;
    for (int guard = 0; guard < 100000; guard++) {
        usart_silicon();
        if (!((u.CR1 & USART_CR1_TXEIE) && (u.SR & USART_SR_TXE))) return;
        USART3_IRQHandler();
    }
    FAIL() << "the TXE interrupt never stopped";
}

class Console : public ::testing::Test {
protected:
    void SetUp() override {
        epuck2_model_usart3 = {};
        epuck2_model_usart3.DR = TAKEN;
        epuck2_model_usart3.SR = USART_SR_TXE;
        epuck2_model_gpiod = {};
        epuck2_model_rcc = {};
        line.clear();
        transmitter_dead = false;
        epuck2_model_polls = 0;
        epuck2_model_silicon = usart_silicon;
        epuck2_console_init(EPUCK2_APB1_HZ);
    }
    void TearDown() override { epuck2_model_silicon = nullptr; }
    void write(const std::string &s) { epuck2_console_write(s.data(), (uint32_t)s.size()); }
};

TEST_F(Console, Usart3At115200BaudOnPD8AndPD9) {
    const stm32_usart &u = epuck2_model_usart3;
    EXPECT_TRUE(epuck2_model_rcc.APB1ENR & RCC_APB1ENR_USART3EN);
    EXPECT_TRUE(epuck2_model_rcc.AHB1ENR & RCC_AHB1ENR_GPIODEN);
    EXPECT_EQ(365u, u.BRR) << "42 MHz / 115200 = 22 + 13/16 (RM0090 table 136)";
    double baud = 42e6 / (u.BRR / 16.0) / 16.0;
    EXPECT_NEAR(115200.0, baud, 115200.0 * 0.002);
    EXPECT_EQ(USART_CR1_UE | USART_CR1_TE, u.CR1) << "8N1, transmitter on, no interrupt yet";
    EXPECT_EQ(0u, u.CR2) << "1 stop bit";
    EXPECT_EQ(GPIO_MODE_ALTERNATE, (epuck2_model_gpiod.MODER >> 16) & 3u) << "PD8";
    EXPECT_EQ(GPIO_MODE_ALTERNATE, (epuck2_model_gpiod.MODER >> 18) & 3u) << "PD9";
    EXPECT_EQ(7u, epuck2_model_gpiod.AFR[1] & 0xFu) << "PD8 AF7";
    EXPECT_EQ(7u, (epuck2_model_gpiod.AFR[1] >> 4) & 0xFu) << "PD9 AF7";
}

TEST_F(Console, TheBaudRateFollowsTheBusClock) {
    epuck2_console_init(16000000u); // the clock tree did not start: HSI
    EXPECT_EQ(139u, epuck2_model_usart3.BRR) << "16 MHz / 115200, rounded";
}

TEST_F(Console, BytesGoOutOnTxeInterruptsInOrder) {
    write("hello, e-puck2\n");
    EXPECT_TRUE(line.empty()) << "a print does not wait for the line";
    EXPECT_TRUE(epuck2_model_usart3.CR1 & USART_CR1_TXEIE);
    run_interrupts();
    EXPECT_EQ("hello, e-puck2\n", line);
    EXPECT_FALSE(epuck2_model_usart3.CR1 & USART_CR1_TXEIE) << "quiet once the buffer is empty";
    EXPECT_EQ(0u, epuck2_console_full_waits());
}

TEST_F(Console, AFullBufferMakesTheWriterWaitAndLosesNothing) {
    std::string text;
    for (int i = 0; i < 1000; i++) text += (char)('a' + i % 26);
    write(text); // four times the buffer, no interrupt served meanwhile
    run_interrupts();
    EXPECT_EQ(text, line);
    EXPECT_EQ(1000u - EPUCK2_CONSOLE_BUFFER_BYTES, epuck2_console_full_waits());
    EXPECT_EQ(0u, epuck2_console_lost());
}

TEST_F(Console, TheInterruptKeepsOutWhileTheWriterHoldsTheBuffer) {
    write("ab");
    // An interrupt pended before the writer cleared TXEIE, taken late:
    epuck2_model_usart3.CR1 &= ~USART_CR1_TXEIE;
    USART3_IRQHandler();
    usart_silicon();
    EXPECT_TRUE(line.empty());
    epuck2_model_usart3.CR1 |= USART_CR1_TXEIE;
    run_interrupts();
    EXPECT_EQ("ab", line);
}

TEST_F(Console, ADeadTransmitterCostsBoundedTimeAndIsCounted) {
    transmitter_dead = true;
    epuck2_model_usart3.SR = 0;
    std::string text(EPUCK2_CONSOLE_BUFFER_BYTES + 3, 'x');
    write(text);
    EXPECT_EQ(3u, epuck2_console_lost());
    EXPECT_LE(epuck2_model_polls, 3u * EPUCK2_CONSOLE_TXE_POLLS);
}

TEST_F(Console, FlushSendsEverythingWithoutInterrupts) {
    write("halt: status 3\n");
    epuck2_console_flush();
    usart_silicon();
    EXPECT_EQ("halt: status 3\n", line);
}

}  // namespace
