/* The STM32F407's peripherals the e-puck2's drivers use (RM0090: GPIO
 * 8.4, general-purpose timers 18.4, basic timers 20.4, RCC 7.3, ADC 13.13,
 * DMA 10.5, DCMI 15.8, I2C 27.6, SPI 28.5, USART 30.6, PWR 5.4, flash 3.9), as structs at their addresses.
 * Built with EPUCK2_REGISTER_MODEL (host tests), each is an ordinary struct
 * in RAM instead: the test plays the hardware, reading what the driver
 * wrote and applying what the silicon would (a BSRR write to ODR, a timer's
 * update flag). A driver that waits for the hardware calls STM32_POLL()
 * each time round its loop: nothing on the robot, the test's model of the
 * silicon on the host (epuck2_model_poll), which acts there as the
 * peripheral would meanwhile. */
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

typedef struct stm32_i2c {
    volatile uint32_t CR1, CR2, OAR1, OAR2, DR, SR1, SR2, CCR, TRISE, FLTR;
} stm32_i2c;

typedef struct stm32_spi {
    volatile uint32_t CR1, CR2, SR, DR, CRCPR, RXCRCR, TXCRCR, I2SCFGR, I2SPR;
} stm32_spi;

typedef struct stm32_dcmi {
    volatile uint32_t CR, SR, RIS, IER, MIS, ICR, ESCR, ESUR, CWSTRT, CWSIZE, DR;
} stm32_dcmi;

typedef struct stm32_dma_stream {
    volatile uint32_t CR, NDTR, PAR, M0AR, M1AR, FCR;
} stm32_dma_stream;

typedef struct stm32_dma {
    volatile uint32_t LISR, HISR, LIFCR, HIFCR;
    stm32_dma_stream S[8];
} stm32_dma;

/* RCC's clock control (RM0090 7.3.1-7.3.3): CR at 0x40023800. */
typedef struct stm32_rcc_clocks {
    volatile uint32_t CR, PLLCFGR, CFGR;
} stm32_rcc_clocks;

typedef struct stm32_usart {
    volatile uint32_t SR, DR, BRR, CR1, CR2, CR3, GTPR;
} stm32_usart;

typedef struct stm32_rcc_enables {
    volatile uint32_t AHB1ENR, AHB2ENR, AHB3ENR, reserved, APB1ENR, APB2ENR;
} stm32_rcc_enables;

#define RCC_CR_HSEON (1u << 16)
#define RCC_CR_HSERDY (1u << 17)
#define RCC_CR_HSEBYP (1u << 18)
#define RCC_CR_PLLON (1u << 24)
#define RCC_CR_PLLRDY (1u << 25)
#define RCC_PLLCFGR_PLLSRC_HSE (1u << 22)
#define RCC_CFGR_SW_MASK 3u
#define RCC_CFGR_SW_PLL 2u
#define RCC_CFGR_SWS_MASK (3u << 2)
#define RCC_CFGR_SWS_PLL (2u << 2)
#define RCC_CFGR_PPRE1_DIV4 (5u << 10)
#define RCC_CFGR_PPRE2_DIV2 (4u << 13)
#define RCC_APB1ENR_PWREN (1u << 28)
#define RCC_APB1ENR_USART3EN (1u << 18)
#define RCC_APB1ENR_TIM6EN (1u << 4)
#define PWR_CR_VOS_SCALE1 (1u << 14)
#define FLASH_ACR_LATENCY_MASK 7u
#define FLASH_ACR_PRFTEN (1u << 8)
#define FLASH_ACR_ICEN (1u << 9)
#define FLASH_ACR_DCEN (1u << 10)

#define USART_SR_TXE (1u << 7)
#define USART_CR1_TE (1u << 3)
#define USART_CR1_TXEIE (1u << 7)
#define USART_CR1_UE (1u << 13)
#define TIM_CR1_OPM (1u << 3)

/* ADC prescaler /8 in the common control register: APB2's 84 MHz / 8. */
#define ADC_CCR_ADCPRE_DIV8 (3u << 16)

#define GPIO_MODE_INPUT 0u
#define GPIO_MODE_OUTPUT 1u
#define GPIO_MODE_ALTERNATE 2u
#define GPIO_PULL_DOWN 2u
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
#define RCC_AHB1ENR_GPIOAEN (1u << 0)
#define RCC_AHB1ENR_GPIODEN (1u << 3)
#define RCC_AHB1ENR_DMA2EN (1u << 22)
#define RCC_AHB2ENR_DCMIEN (1u << 0)
#define RCC_APB1ENR_TIM5EN (1u << 3)
#define RCC_APB1ENR_TIM7EN (1u << 5)
#define RCC_APB1ENR_I2C1EN (1u << 21)
#define RCC_APB2ENR_SPI1EN (1u << 12)

#define TIM_CCMR1_OC1PE (1u << 3)
#define TIM_CCMR1_OC1M_PWM1 (6u << 4)
#define TIM_CCER_CC1E (1u << 0)

#define I2C_CR1_PE (1u << 0)
#define I2C_CR1_START (1u << 8)
#define I2C_CR1_STOP (1u << 9)
#define I2C_SR1_SB (1u << 0)
#define I2C_SR1_ADDR (1u << 1)
#define I2C_SR1_BTF (1u << 2)
#define I2C_SR1_TXE (1u << 7)
#define I2C_SR1_BERR (1u << 8)
#define I2C_SR1_ARLO (1u << 9)
#define I2C_SR1_AF (1u << 10)
#define I2C_CCR_FS (1u << 15)

#define SPI_CR1_MSTR (1u << 2)
#define SPI_CR1_BR_DIV8 (2u << 3)
#define SPI_CR1_SPE (1u << 6)
#define SPI_CR1_SSI (1u << 8)
#define SPI_CR1_SSM (1u << 9)
#define SPI_SR_RXNE (1u << 0)
#define SPI_SR_TXE (1u << 1)
#define SPI_SR_BSY (1u << 7)

#define DCMI_CR_CAPTURE (1u << 0)
#define DCMI_CR_CM_SNAPSHOT (1u << 1)
#define DCMI_CR_PCKPOL (1u << 5)
#define DCMI_CR_HSPOL (1u << 6)
#define DCMI_CR_VSPOL (1u << 7)
#define DCMI_CR_EDM_MASK (3u << 10)
#define DCMI_CR_ENABLE (1u << 14)
#define DCMI_IT_FRAME (1u << 0) /* RIS, IER, ICR alike */
#define DCMI_IT_OVR (1u << 1)
#define DCMI_IT_ERR (1u << 2)

#define DMA_SxCR_EN (1u << 0)
#define DMA_SxCR_DMEIE (1u << 1)
#define DMA_SxCR_TEIE (1u << 2)
#define DMA_SxCR_TCIE (1u << 4)
#define DMA_SxCR_DIR_MASK (3u << 6) /* 00: peripheral to memory */
#define DMA_SxCR_CIRC (1u << 8)
#define DMA_SxCR_MINC (1u << 10)
#define DMA_SxCR_PSIZE_WORD (2u << 11)
#define DMA_SxCR_MSIZE_WORD (2u << 13)
#define DMA_SxCR_PL_VERY_HIGH (3u << 16)
#define DMA_SxCR_CHSEL(c) ((uint32_t)(c) << 25)
#define DMA_SxFCR_FTH_FULL (3u << 0)
#define DMA_SxFCR_DMDIS (1u << 2)
/* A stream's flags in LISR/LIFCR: stream 1's are stream 0's shifted by 6. */
#define DMA_STREAM1_SHIFT 6u
#define DMA_FLAG_FE (1u << 0)
#define DMA_FLAG_DME (1u << 2)
#define DMA_FLAG_TE (1u << 3)
#define DMA_FLAG_HT (1u << 4)
#define DMA_FLAG_TC (1u << 5)
#define DMA_FLAGS_ALL (DMA_FLAG_FE | DMA_FLAG_DME | DMA_FLAG_TE | DMA_FLAG_HT | DMA_FLAG_TC)

#define TIM2_IRQ 28
#define TIM3_IRQ 29
#define ADC_IRQ 18
#define TIM4_IRQ 30
#define TIM7_IRQ 55
#define DMA2_STREAM1_IRQ 57
#define DCMI_IRQ 78
#define USART3_IRQ 39
#define TIM6_DAC_IRQ 54

#ifdef EPUCK2_REGISTER_MODEL
extern stm32_gpio epuck2_model_gpiob, epuck2_model_gpioc, epuck2_model_gpioe;
extern stm32_timer epuck2_model_tim2, epuck2_model_tim3, epuck2_model_tim4;
extern stm32_adc epuck2_model_adc2;
extern volatile uint32_t epuck2_model_adc_ccr;
extern stm32_rcc_enables epuck2_model_rcc;
extern stm32_gpio epuck2_model_gpioa, epuck2_model_gpiod;
extern stm32_timer epuck2_model_tim5, epuck2_model_tim7;
extern stm32_i2c epuck2_model_i2c1;
extern stm32_spi epuck2_model_spi1;
extern stm32_dcmi epuck2_model_dcmi;
extern stm32_dma epuck2_model_dma2;
extern stm32_rcc_clocks epuck2_model_rcc_clocks;
extern volatile uint32_t epuck2_model_flash_acr, epuck2_model_pwr_cr;
extern stm32_usart epuck2_model_usart3;
extern stm32_timer epuck2_model_tim6;
void epuck2_model_poll(void);
#define RCC_CLOCKS (&epuck2_model_rcc_clocks)
#define FLASH_ACR epuck2_model_flash_acr
#define PWR_CR epuck2_model_pwr_cr
#define USART3 (&epuck2_model_usart3)
#define TIM6 (&epuck2_model_tim6)
#define STM32_POLL() epuck2_model_poll()
#define GPIOA (&epuck2_model_gpioa)
#define GPIOD (&epuck2_model_gpiod)
#define TIM5 (&epuck2_model_tim5)
#define TIM7 (&epuck2_model_tim7)
#define I2C1 (&epuck2_model_i2c1)
#define SPI1 (&epuck2_model_spi1)
#define DCMI (&epuck2_model_dcmi)
#define DMA2 (&epuck2_model_dma2)
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
#define STM32_POLL() ((void)0)
#define GPIOA ((stm32_gpio *)0x40020000u)
#define GPIOD ((stm32_gpio *)0x40020C00u)
#define TIM5 ((stm32_timer *)0x40000C00u)
#define TIM7 ((stm32_timer *)0x40001400u)
#define I2C1 ((stm32_i2c *)0x40005400u)
#define SPI1 ((stm32_spi *)0x40013000u)
#define DCMI ((stm32_dcmi *)0x50050000u)
#define DMA2 ((stm32_dma *)0x40026400u)
#define RCC_CLOCKS ((stm32_rcc_clocks *)0x40023800u)
#define FLASH_ACR (*(volatile uint32_t *)0x40023C00u)
#define PWR_CR (*(volatile uint32_t *)0x40007000u)
#define USART3 ((stm32_usart *)0x40004800u)
#define TIM6 ((stm32_timer *)0x40001000u)
#endif

/* APB1 itself runs at 42 MHz (I2C's clock), APB2 at 84 MHz (SPI1's). */
#define EPUCK2_APB1_HZ 42000000u
#define EPUCK2_APB2_HZ 84000000u

/* APB1's timers count at 84 MHz once the clock tree runs the core at
 * 168 MHz (APB1 at 42 MHz, its timers at twice that: RM0090 6.2). */
#define EPUCK2_APB1_TIMER_HZ 84000000u

/* A pin's mode (2 bits a pin in MODER). */
static inline void stm32_gpio_mode(stm32_gpio *port, unsigned pin, uint32_t mode) {
    port->MODER = (port->MODER & ~(3u << (2u * pin))) | (mode << (2u * pin));
}

/* A pin's alternate function (4 bits a pin in AFR[0] for 0..7, AFR[1]
 * for 8..15), and the pin switched to it. */
static inline void stm32_gpio_af(stm32_gpio *port, unsigned pin, uint32_t af) {
    volatile uint32_t *afr = &port->AFR[pin / 8u];
    unsigned shift = 4u * (pin % 8u);
    *afr = (*afr & ~(0xFu << shift)) | (af << shift);
    stm32_gpio_mode(port, pin, GPIO_MODE_ALTERNATE);
}

static inline void stm32_gpio_pull(stm32_gpio *port, unsigned pin, uint32_t pull) {
    port->PUPDR = (port->PUPDR & ~(3u << (2u * pin))) | (pull << (2u * pin));
}

#endif
