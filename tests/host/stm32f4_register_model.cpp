// The STM32F407 peripherals of the e-puck2's drivers as plain memory
// (ports/epuck/epuck2/drivers/stm32f4_registers.h, EPUCK2_REGISTER_MODEL):
// the driver tests play the silicon on them.
extern "C" {
#include "../../ports/epuck/epuck2/drivers/stm32f4_registers.h"
stm32_gpio epuck2_model_gpiob, epuck2_model_gpioc, epuck2_model_gpioe;
stm32_timer epuck2_model_tim2, epuck2_model_tim3, epuck2_model_tim4;
stm32_adc epuck2_model_adc2;
volatile uint32_t epuck2_model_adc_ccr;
stm32_rcc_enables epuck2_model_rcc;
}
