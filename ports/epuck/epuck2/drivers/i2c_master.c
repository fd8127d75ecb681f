/* The e-puck2's I2C master, polled: writes are few (the camera's set-up)
 * and short (a byte at 400 kHz takes 22.5 us), so an interrupt-driven
 * driver would buy nothing. Each wait is bounded: a device that holds the
 * bus or an I2C block that never answers makes a write fail, it does not
 * hang the robot. Facts: ports/epuck/README.md. */
#include "i2c_master.h"

#include "stm32f4_registers.h"

#define BUS_HZ 400000u
#define PIN_SCL 8u
#define PIN_SDA 9u
#define AF_I2C1 4u
/* About 4 ms (the e-puck2 firmware's I2C timeout) at 168 MHz: a poll is an
 * APB1 read, more than 8 core cycles at APB1's 42 MHz. */
#define TIMEOUT_POLLS 84000u
#define BUS_ERRORS (I2C_SR1_AF | I2C_SR1_BERR | I2C_SR1_ARLO)

void epuck2_i2c_init(void) {
    RCC_ENABLES->AHB1ENR |= RCC_AHB1ENR_GPIOBEN;
    RCC_ENABLES->APB1ENR |= RCC_APB1ENR_I2C1EN;
    GPIOB->OTYPER |= (1u << PIN_SCL) | (1u << PIN_SDA); /* open drain: I2C's wired-AND */
    stm32_gpio_af(GPIOB, PIN_SCL, AF_I2C1);
    stm32_gpio_af(GPIOB, PIN_SDA, AF_I2C1);
    I2C1->CR1 = 0; /* timing is set with the block off */
    I2C1->CR2 = EPUCK2_APB1_HZ / 1000000u;
    /* Fast mode, duty 2: a bit is 3 CCR periods of APB1 (one high, two low). */
    I2C1->CCR = I2C_CCR_FS | EPUCK2_APB1_HZ / (3u * BUS_HZ);
    /* The longest rise time fast mode allows, 300 ns, in APB1 periods, + 1. */
    I2C1->TRISE = EPUCK2_APB1_HZ / 1000000u * 300u / 1000u + 1u;
    I2C1->CR1 = I2C_CR1_PE;
}

/* Until SR1 shows flag; false on a bus error or a NACK, or in time. */
static bool wait_for(uint32_t flag) {
    for (uint32_t n = 0; n < TIMEOUT_POLLS; n++) {
        STM32_POLL();
        uint32_t sr1 = I2C1->SR1;
        if (sr1 & BUS_ERRORS) return false;
        if (sr1 & flag) return true;
    }
    return false;
}

bool epuck2_i2c_write(uint8_t address, uint8_t reg, uint8_t value) {
    /* What each byte waits for: ADDR after the address (then, once SR2 is
     * read, the data register is free), TXE after reg, BTF after the last
     * so the STOP does not cut it short. */
    const uint8_t bytes[3] = {(uint8_t)(address << 1), reg, value};
    static const uint32_t sent[3] = {I2C_SR1_ADDR, I2C_SR1_TXE, I2C_SR1_BTF};
    I2C1->CR1 |= I2C_CR1_START;
    bool ok = wait_for(I2C_SR1_SB);
    for (unsigned i = 0; ok && i < 3u; i++) {
        I2C1->DR = bytes[i];
        ok = wait_for(sent[i]);
        if (ok && i == 0u) (void)I2C1->SR2; /* SR1 then SR2 read: ADDR cleared */
    }
    I2C1->SR1 = ~BUS_ERRORS; /* rc_w0: the error flags cleared, for the next write */
    I2C1->CR1 |= I2C_CR1_STOP;
    return ok;
}
