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

typedef struct stm32_rcc_enables {
    volatile uint32_t AHB1ENR, AHB2ENR, AHB3ENR, reserved, APB1ENR, APB2ENR;
} stm32_rcc_enables;

#define GPIO_MODE_OUTPUT 1u
#define TIM_CR1_CEN (1u << 0)
#define TIM_CR1_ARPE (1u << 7)
#define TIM_DIER_UIE (1u << 0)
#define TIM_SR_UIF (1u << 0)
#define TIM_EGR_UG (1u << 0)
#define RCC_AHB1ENR_GPIOEEN (1u << 4)
#define RCC_APB1ENR_TIM3EN (1u << 1)
#define RCC_APB1ENR_TIM4EN (1u << 2)

#define TIM3_IRQ 29
#define TIM4_IRQ 30

#ifdef EPUCK2_REGISTER_MODEL
extern stm32_gpio epuck2_model_gpioe;
extern stm32_timer epuck2_model_tim3, epuck2_model_tim4;
extern stm32_rcc_enables epuck2_model_rcc;
#define GPIOE (&epuck2_model_gpioe)
#define TIM3 (&epuck2_model_tim3)
#define TIM4 (&epuck2_model_tim4)
#define RCC_ENABLES (&epuck2_model_rcc)
#else
#define GPIOE ((stm32_gpio *)0x40021000u)
#define TIM3 ((stm32_timer *)0x40000400u)
#define TIM4 ((stm32_timer *)0x40000800u)
#define RCC_ENABLES ((stm32_rcc_enables *)0x40023830u)
#endif

/* APB1's timers count at 84 MHz once the clock tree runs the core at
 * 168 MHz (APB1 at 42 MHz, its timers at twice that: RM0090 6.2). */
#define EPUCK2_APB1_TIMER_HZ 84000000u

#endif
