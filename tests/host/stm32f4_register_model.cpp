// The STM32F407 peripherals of the e-puck2's drivers as plain memory
// (ports/epuck/epuck2/drivers/stm32f4_registers.h, EPUCK2_REGISTER_MODEL):
// the driver tests play the silicon on them.
#include "stm32f4_register_model.hpp"

extern "C" {
#include "../../ports/epuck/epuck2/drivers/stm32f4_registers.h"
stm32_gpio epuck2_model_gpioa, epuck2_model_gpiob, epuck2_model_gpioc, epuck2_model_gpiod, epuck2_model_gpioe;
stm32_timer epuck2_model_tim2, epuck2_model_tim3, epuck2_model_tim4, epuck2_model_tim5, epuck2_model_tim7;
stm32_adc epuck2_model_adc2;
volatile uint32_t epuck2_model_adc_ccr;
stm32_rcc_enables epuck2_model_rcc;
stm32_i2c epuck2_model_i2c1;
stm32_spi epuck2_model_spi1;
stm32_dcmi epuck2_model_dcmi;
stm32_dma epuck2_model_dma2;
stm32_rcc_clocks epuck2_model_rcc_clocks;
volatile uint32_t epuck2_model_flash_acr, epuck2_model_pwr_cr;
stm32_usart epuck2_model_usart3;
stm32_timer epuck2_model_tim6;

void epuck2_model_poll(void) {
    epuck2_model_polls++;
    if (epuck2_model_silicon) epuck2_model_silicon();
}
}

std::function<void()> epuck2_model_silicon;
uint64_t epuck2_model_polls;

void epuck2_model_apply_bsrr(stm32_gpio &port) {
    uint32_t bsrr = port.BSRR;
    port.ODR = (port.ODR | (bsrr & 0xFFFFu)) & ~(bsrr >> 16);
    port.BSRR = 0;
}
