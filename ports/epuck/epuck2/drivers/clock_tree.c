/* The e-puck2's clock tree, as GCtronic's firmware configures it (src/
 * mcuconf.h: HSE 24 MHz, PLLM 24, PLLN 336, PLLP 2, PLLQ 7, AHB /1, APB1
 * /4, APB2 /2; board.h: STM32_HSECLK 24000000, STM32_HSE_BYPASS), in the
 * order RM0090 asks (6.3.2 RCC_CR, 6.3.3 RCC_PLLCFGR, 6.3.4 RCC_CFGR,
 * 3.5.1 the flash's wait states before a faster clock, 5.4.1 voltage
 * scale 1 for 168 MHz). Facts: ports/epuck/README.md. */
#include "clock_tree.h"

#include <stdbool.h>

#include "stm32f4_registers.h"

#define PLLM 24u  /* 24 MHz / 24: the 1 MHz VCO input RM0090 recommends (6.3.2) */
#define PLLN 336u /* VCO at 336 MHz */
#define PLLP_DIV2 0u /* 336 / 2 = 168 MHz */
#define PLLQ 7u   /* 336 / 7 = 48 MHz for USB */
/* RM0090 table 10: 5 wait states from 150 to 168 MHz at 2.7-3.6 V (the
 * e-puck2 runs at 3.0 V: board.h STM32_VDD 300). */
#define FLASH_WAIT_STATES 5u

static bool wait_until(volatile uint32_t *reg, uint32_t mask, uint32_t value) {
    for (uint32_t n = 0; n < EPUCK2_CLOCK_WAIT_POLLS; n++) {
        STM32_POLL();
        if ((*reg & mask) == value) return true;
    }
    return false;
}

/* Back to the internal clock's undivided buses: what the console's baud
 * rate is then computed from. */
static epuck2_clock_status give_up(epuck2_clock_status why) {
    RCC_CLOCKS->CFGR = 0;
    return why;
}

epuck2_clock_status epuck2_clock_tree_start(void) {
    RCC_ENABLES->APB1ENR |= RCC_APB1ENR_PWREN;
    PWR_CR |= PWR_CR_VOS_SCALE1;
    /* HSEBYP may be written only while the HSE is off (RM0090 6.3.1). */
    RCC_CLOCKS->CR |= RCC_CR_HSEBYP;
    RCC_CLOCKS->CR |= RCC_CR_HSEON;
    if (!wait_until(&RCC_CLOCKS->CR, RCC_CR_HSERDY, RCC_CR_HSERDY)) return give_up(EPUCK2_CLOCKS_NO_HSE);
    RCC_CLOCKS->PLLCFGR = PLLM | (PLLN << 6) | (PLLP_DIV2 << 16) | RCC_PLLCFGR_PLLSRC_HSE | (PLLQ << 24);
    RCC_CLOCKS->CR |= RCC_CR_PLLON;
    if (!wait_until(&RCC_CLOCKS->CR, RCC_CR_PLLRDY, RCC_CR_PLLRDY)) return give_up(EPUCK2_CLOCKS_NO_PLL);
    FLASH_ACR = FLASH_WAIT_STATES | FLASH_ACR_PRFTEN | FLASH_ACR_ICEN | FLASH_ACR_DCEN;
    /* The buses' dividers first, so neither runs over its limit (APB1 42,
     * APB2 84 MHz) for a moment when the core speeds up. */
    RCC_CLOCKS->CFGR = RCC_CFGR_PPRE1_DIV4 | RCC_CFGR_PPRE2_DIV2;
    RCC_CLOCKS->CFGR |= RCC_CFGR_SW_PLL;
    if (!wait_until(&RCC_CLOCKS->CFGR, RCC_CFGR_SWS_MASK, RCC_CFGR_SWS_PLL))
        return give_up(EPUCK2_CLOCKS_NO_SWITCH);
    return EPUCK2_CLOCKS_RUNNING;
}

const char *epuck2_clock_status_text(epuck2_clock_status status) {
    switch (status) {
    case EPUCK2_CLOCKS_RUNNING: return "the core runs at 168 MHz";
    case EPUCK2_CLOCKS_NO_HSE: return "the 24 MHz external clock (HSE) never became ready";
    case EPUCK2_CLOCKS_NO_PLL: return "the PLL never locked";
    case EPUCK2_CLOCKS_NO_SWITCH: return "the core never switched to the PLL";
    }
    return "unknown clock status";
}
