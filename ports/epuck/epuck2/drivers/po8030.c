/* The PO8030's set-up. Its registers are in banks (A: timing and window,
 * B: output format and scaler), chosen through register 0x03 of every bank.
 * With the scaler at 1/4 in both directions the window is counted in
 * output pixels: 1..160 x 1..120 is then the whole 640 x 480 array, a
 * frame of 38400 bytes that fits the STM32's RAM (a VGA frame, 600 KB,
 * would not). The auto-exposure windows follow: all of it, and its middle
 * third for the centre. Register addresses and values: GCtronic's e-puck2
 * firmware (src/camera/po8030.c, its QQVGA and RGB565 set-up); see
 * ports/epuck/README.md. */
#include "po8030.h"

#include <stdint.h>

#include "i2c_master.h"
#include "stm32f4_registers.h"

#define PO8030_ADDRESS 0x6Eu /* 7 bits: 0xDC on the bus to write */

#define REG_BANK 0x03u
#define BANK_A 0x00u
#define BANK_B 0x01u

/* Bank A */
#define REG_WINDOW_X1 0x08u /* then X1 low, Y1, X2, Y2: high byte first */
#define REG_VSYNC_START_ROW_L 0x11u
#define REG_AE_FULL_X1 0x35u /* X1, X2, Y1, Y2 */
#define REG_AE_CENTRE_X1 0x3Du
#define REG_PAD_CONTROL 0x5Bu
/* Bank B */
#define REG_FORMAT 0x4Eu
#define REG_SCALE_X 0x93u
#define REG_SCALE_Y 0x94u
#define REG_SCALE_TH_H 0x95u
#define REG_SCALE_TH_L 0x96u
#define REG_SYNC_CONTROL0 0xB7u

#define FORMAT_RGB565 0x30u
#define SCALE_QUARTER 0x80u /* 0x20 is 1:1 */
#define SCALE_THRESHOLD 0x00F5u /* the firmware's for 160 wide, two bytes a pixel */
#define VSYNC_START_ROW 0x0Au   /* the firmware's for every format but Y only */

#define W EPUCK2_CAMERA_WIDTH
#define H EPUCK2_CAMERA_HEIGHT
#define HI(v) ((uint8_t)((v) >> 8))
#define LO(v) ((uint8_t)((v)&0xFFu))
/* A 16-bit register pair at r, r + 1, high byte first. */
#define PAIR(r, v) {(r), HI(v)}, {(uint8_t)((r) + 1u), LO(v)}

static const struct {
    uint8_t reg, value;
} setup[] = {
    {REG_BANK, BANK_A},
    {REG_PAD_CONTROL, 0x00},
    {REG_VSYNC_START_ROW_L, VSYNC_START_ROW},
    PAIR(REG_WINDOW_X1, 1u), PAIR(REG_WINDOW_X1 + 2u, 1u),
    PAIR(REG_WINDOW_X1 + 4u, W), PAIR(REG_WINDOW_X1 + 6u, H),
    PAIR(REG_AE_FULL_X1, 1u), PAIR(REG_AE_FULL_X1 + 2u, W),
    PAIR(REG_AE_FULL_X1 + 4u, 1u), PAIR(REG_AE_FULL_X1 + 6u, H),
    PAIR(REG_AE_CENTRE_X1, 1u + W / 3u), PAIR(REG_AE_CENTRE_X1 + 2u, 1u + 2u * W / 3u),
    PAIR(REG_AE_CENTRE_X1 + 4u, 1u + H / 3u), PAIR(REG_AE_CENTRE_X1 + 6u, 1u + 2u * H / 3u),
    {REG_BANK, BANK_B},
    {REG_FORMAT, FORMAT_RGB565},
    {REG_SYNC_CONTROL0, 0x00},
    {REG_SCALE_X, SCALE_QUARTER},
    {REG_SCALE_Y, SCALE_QUARTER},
    {REG_SCALE_TH_H, HI(SCALE_THRESHOLD)},
    {REG_SCALE_TH_L, LO(SCALE_THRESHOLD)},
};

#define MCLK_PIN 0u /* PA0: TIM5 channel 1 */
#define AF_TIM5 2u

/* 21 MHz, as the firmware clocks it: TIM5's 84 MHz over a period of 4,
 * high for 2 of them. */
static void start_clock(void) {
    RCC_ENABLES->AHB1ENR |= RCC_AHB1ENR_GPIOAEN;
    RCC_ENABLES->APB1ENR |= RCC_APB1ENR_TIM5EN;
    stm32_gpio_af(GPIOA, MCLK_PIN, AF_TIM5);
    TIM5->PSC = 0;
    TIM5->ARR = 3;
    TIM5->CCR[0] = 2;
    TIM5->CCMR1 = TIM_CCMR1_OC1M_PWM1 | TIM_CCMR1_OC1PE;
    TIM5->CCER = TIM_CCER_CC1E;
    TIM5->EGR = TIM_EGR_UG;
    TIM5->CR1 = TIM_CR1_CEN;
}

bool epuck2_po8030_init(void) {
    start_clock(); /* before the registers, as the firmware does it */
    for (unsigned i = 0; i < sizeof setup / sizeof setup[0]; i++)
        if (!epuck2_i2c_write(PO8030_ADDRESS, setup[i].reg, setup[i].value)) return false;
    return true;
}
