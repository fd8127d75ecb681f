/* The STM32F405/407 vector table (RM0090, table 61: 82 interrupts).
 * Every handler is weak: a driver defines TIM3_IRQHandler and the like,
 * the rest lead to unexpected_interrupt, which names the interrupt and
 * stops the board (an enabled interrupt without a handler is a bug). */
#include "openswarm/cortex_m4.h"

#include <stdint.h>

extern uint32_t _estack[];
void Reset_Handler(void);
void unexpected_interrupt(void);

#define HANDLER(name) void name(void) __attribute__((weak, alias("unexpected_interrupt")));
#define CORE_HANDLERS(X)                                                                        \
    X(NMI_Handler) X(HardFault_Handler) X(MemManage_Handler) X(BusFault_Handler)               \
    X(UsageFault_Handler) X(SVC_Handler) X(DebugMon_Handler) X(PendSV_Handler)                 \
    X(SysTick_Handler)
#define DEVICE_HANDLERS(X)                                                                      \
    X(WWDG_IRQHandler) X(PVD_IRQHandler) X(TAMP_STAMP_IRQHandler) X(RTC_WKUP_IRQHandler)       \
    X(FLASH_IRQHandler) X(RCC_IRQHandler) X(EXTI0_IRQHandler) X(EXTI1_IRQHandler)              \
    X(EXTI2_IRQHandler) X(EXTI3_IRQHandler) X(EXTI4_IRQHandler) X(DMA1_Stream0_IRQHandler)     \
    X(DMA1_Stream1_IRQHandler) X(DMA1_Stream2_IRQHandler) X(DMA1_Stream3_IRQHandler)           \
    X(DMA1_Stream4_IRQHandler) X(DMA1_Stream5_IRQHandler) X(DMA1_Stream6_IRQHandler)           \
    X(ADC_IRQHandler) X(CAN1_TX_IRQHandler) X(CAN1_RX0_IRQHandler) X(CAN1_RX1_IRQHandler)      \
    X(CAN1_SCE_IRQHandler) X(EXTI9_5_IRQHandler) X(TIM1_BRK_TIM9_IRQHandler)                   \
    X(TIM1_UP_TIM10_IRQHandler) X(TIM1_TRG_COM_TIM11_IRQHandler) X(TIM1_CC_IRQHandler)         \
    X(TIM2_IRQHandler) X(TIM3_IRQHandler) X(TIM4_IRQHandler) X(I2C1_EV_IRQHandler)             \
    X(I2C1_ER_IRQHandler) X(I2C2_EV_IRQHandler) X(I2C2_ER_IRQHandler) X(SPI1_IRQHandler)       \
    X(SPI2_IRQHandler) X(USART1_IRQHandler) X(USART2_IRQHandler) X(USART3_IRQHandler)          \
    X(EXTI15_10_IRQHandler) X(RTC_Alarm_IRQHandler) X(OTG_FS_WKUP_IRQHandler)                  \
    X(TIM8_BRK_TIM12_IRQHandler) X(TIM8_UP_TIM13_IRQHandler) X(TIM8_TRG_COM_TIM14_IRQHandler)  \
    X(TIM8_CC_IRQHandler) X(DMA1_Stream7_IRQHandler) X(FSMC_IRQHandler) X(SDIO_IRQHandler)     \
    X(TIM5_IRQHandler) X(SPI3_IRQHandler) X(UART4_IRQHandler) X(UART5_IRQHandler)              \
    X(TIM6_DAC_IRQHandler) X(TIM7_IRQHandler) X(DMA2_Stream0_IRQHandler)                       \
    X(DMA2_Stream1_IRQHandler) X(DMA2_Stream2_IRQHandler) X(DMA2_Stream3_IRQHandler)           \
    X(DMA2_Stream4_IRQHandler) X(ETH_IRQHandler) X(ETH_WKUP_IRQHandler) X(CAN2_TX_IRQHandler)  \
    X(CAN2_RX0_IRQHandler) X(CAN2_RX1_IRQHandler) X(CAN2_SCE_IRQHandler) X(OTG_FS_IRQHandler)  \
    X(DMA2_Stream5_IRQHandler) X(DMA2_Stream6_IRQHandler) X(DMA2_Stream7_IRQHandler)           \
    X(USART6_IRQHandler) X(I2C3_EV_IRQHandler) X(I2C3_ER_IRQHandler)                           \
    X(OTG_HS_EP1_OUT_IRQHandler) X(OTG_HS_EP1_IN_IRQHandler) X(OTG_HS_WKUP_IRQHandler)         \
    X(OTG_HS_IRQHandler) X(DCMI_IRQHandler) X(CRYP_IRQHandler) X(HASH_RNG_IRQHandler)          \
    X(FPU_IRQHandler)

CORE_HANDLERS(HANDLER)
DEVICE_HANDLERS(HANDLER)

#define ENTRY(name) name,
typedef void (*vector)(void);
__attribute__((section(".vectors"), used)) const vector stm32f407_vectors[16 + 82] = {
    (vector)(uintptr_t)_estack, Reset_Handler,
    NMI_Handler, HardFault_Handler, MemManage_Handler, BusFault_Handler, UsageFault_Handler,
    0, 0, 0, 0, SVC_Handler, DebugMon_Handler, 0, PendSV_Handler, SysTick_Handler,
    DEVICE_HANDLERS(ENTRY)};

/* The active exception number (IPSR) names the culprit: 16 + IRQ. */
void unexpected_interrupt(void) {
    uint32_t ipsr;
    __asm__ __volatile__("mrs %0, ipsr" : "=r"(ipsr));
    static const char text[] = "unexpected interrupt: exception ";
    board_console_write(text, sizeof text - 1);
    char digits[3] = {(char)('0' + ipsr / 100u % 10u), (char)('0' + ipsr / 10u % 10u),
                      (char)('0' + ipsr % 10u)};
    board_console_write(digits, 3);
    board_console_write(" (16 + IRQ number), no handler: stopped\n", 40);
    board_halt(3);
}
