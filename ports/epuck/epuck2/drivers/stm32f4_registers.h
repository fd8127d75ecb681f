/* The STM32F407's peripherals the e-puck2's drivers use (RM0090: GPIO
 * 8.4, general-purpose timers 18.4, RCC 7.3), as structs at their
 * addresses. Built with EPUCK2_REGISTER_MODEL (host tests), each is an
 * ordinary struct in RAM instead: the test plays the hardware, reading
 * what the driver wrote and applying what the silicon would (a BSRR write
 * to ODR, a timer's update flag). */
#ifndef EPUCK2_STM32F4_REGISTERS_H
#define EPUCK2_STM32F4_REGISTERS_H

#include <stdint.h>

typedef struct stm32_gpio {
    volatile uint32_t MODER, OTYPER, OSPEEDR, PUPDR, IDR, ODR, BSRR, LCKR, AFR[2];
} stm32_gpio;

typedef struct stm32_timer {
    volatile uint32_t CR1, CR2, SMCR, DIER, SR, EGR, CCMR1, CCMR2, CCER, CNT, PSC, ARR, RCR, CCR[4],
        BDTR, DCR, DMAR, OR;
} stm32_timer;

typedef struct stm32_adc {
    volatile uint32_t SR, CR1, CR2, SMPR1, SMPR2, JOFR[4], HTR, LTR, SQR1, SQR2, SQR3, JSQR, JDR[4], DR;
} stm32_adc;

typedef struct stm32_rcc_enables {
    volatile uint32_t AHB1ENR, AHB2ENR, AHB3ENR, reserved, APB1ENR, APB2ENR;
} stm32_rcc_enables;

/* ADC prescaler /8 in the common control register: APB2's 84 MHz / 8. */
#define ADC_CCR_ADCPRE_DIV8 (3u << 16)

#define GPIO_MODE_OUTPUT 1u
#define TIM_CR1_CEN (1u << 0)
#define TIM_CR1_ARPE (1u << 7)
#define TIM_DIER_UIE (1u << 0)
#define TIM_SR_UIF (1u << 0)
#define TIM_EGR_UG (1u << 0)
#define TIM_DIER_CC1IE (1u << 1)
#define TIM_DIER_CC2IE (1u << 2)
#define TIM_SR_CC1IF (1u << 1)
#define TIM_SR_CC2IF (1u << 2)
#define ADC_SR_EOC (1u << 1)
#define ADC_CR1_EOCIE (1u << 5)
#define ADC_CR1_SCAN (1u << 8)
#define ADC_CR2_ADON (1u << 0)
#define ADC_CR2_EOCS (1u << 10)
#define ADC_CR2_SWSTART (1u << 30)
#define ADC_SAMPLE_112_CYCLES 6u
#define RCC_AHB1ENR_GPIOBEN (1u << 1)
#define RCC_AHB1ENR_GPIOCEN (1u << 2)
#define RCC_AHB1ENR_GPIOEEN (1u << 4)
#define RCC_APB1ENR_TIM2EN (1u << 0)
#define RCC_APB2ENR_ADC2EN (1u << 9)
#define GPIO_MODE_ANALOG 3u
#define RCC_APB1ENR_TIM3EN (1u << 1)
#define RCC_APB1ENR_TIM4EN (1u << 2)

#define TIM2_IRQ 28
#define TIM3_IRQ 29
#define ADC_IRQ 18
#define TIM4_IRQ 30

#ifdef EPUCK2_REGISTER_MODEL
extern stm32_gpio epuck2_model_gpiob, epuck2_model_gpioc, epuck2_model_gpioe;
extern stm32_timer epuck2_model_tim2, epuck2_model_tim3, epuck2_model_tim4;
extern stm32_adc epuck2_model_adc2;
extern volatile uint32_t epuck2_model_adc_ccr;
extern stm32_rcc_enables epuck2_model_rcc;
#define GPIOB (&epuck2_model_gpiob)
#define GPIOC (&epuck2_model_gpioc)
#define GPIOE (&epuck2_model_gpioe)
#define TIM2 (&epuck2_model_tim2)
#define TIM3 (&epuck2_model_tim3)
#define ADC2 (&epuck2_model_adc2)
#define ADC_COMMON_CCR epuck2_model_adc_ccr
#define TIM4 (&epuck2_model_tim4)
#define RCC_ENABLES (&epuck2_model_rcc)
#else
#define GPIOB ((stm32_gpio *)0x40020400u)
#define GPIOC ((stm32_gpio *)0x40020800u)
#define GPIOE ((stm32_gpio *)0x40021000u)
#define TIM2 ((stm32_timer *)0x40000000u)
#define TIM3 ((stm32_timer *)0x40000400u)
#define ADC2 ((stm32_adc *)0x40012100u)
#define ADC_COMMON_CCR (*(volatile uint32_t *)0x40012304u)
#define TIM4 ((stm32_timer *)0x40000800u)
#define RCC_ENABLES ((stm32_rcc_enables *)0x40023830u)
#endif

/* APB1's timers count at 84 MHz once the clock tree runs the core at
 * 168 MHz (APB1 at 42 MHz, its timers at twice that: RM0090 6.2). */
#define EPUCK2_APB1_TIMER_HZ 84000000u

/* A pin's mode (2 bits a pin in MODER). */
static inline void stm32_gpio_mode(stm32_gpio *port, unsigned pin, uint32_t mode) {
    port->MODER = (port->MODER & ~(3u << (2u * pin))) | (mode << (2u * pin));
}

#endif
