/* The e-puck2's selector. Its bits 0..2 are PC13, PC14, PC15 and bit 3 is
 * PD4, inputs pulled down: a closed contact reads 1, so the position is
 * the four pins as read, no inversion (GCtronic's firmware, board.h and
 * src/selector.c). TIM7, a basic timer, counts at 10 kHz and updates every
 * 500 counts: 20 reads a second, quick enough for a hand turning it; the
 * device layer turns a change into an event. Facts: ports/epuck/README.md. */
#include "selector.h"

#include "stm32f4_registers.h"

#define TIMER_HZ 10000u
#define PERIOD 500u /* counts: 20 Hz */

static const struct {
    stm32_gpio *port;
    uint8_t pin;
} bits[4] = {{GPIOC, 13}, {GPIOC, 14}, {GPIOC, 15}, {GPIOD, 4}};

static epuck2_selector_read position_read;

uint8_t epuck2_selector_position(void) {
    uint8_t position = 0;
    for (unsigned b = 0; b < 4u; b++)
        if (bits[b].port->IDR & (1u << bits[b].pin)) position |= (uint8_t)(1u << b);
    return position;
}

void TIM7_IRQHandler(void) {
    TIM7->SR = ~TIM_SR_UIF; /* rc_w0: the update flag alone */
    if (position_read != 0) position_read(epuck2_selector_position());
}

void epuck2_selector_init(epuck2_selector_read on_read) {
    position_read = on_read;
    RCC_ENABLES->AHB1ENR |= RCC_AHB1ENR_GPIOCEN | RCC_AHB1ENR_GPIODEN;
    RCC_ENABLES->APB1ENR |= RCC_APB1ENR_TIM7EN;
    for (unsigned b = 0; b < 4u; b++) {
        stm32_gpio_mode(bits[b].port, bits[b].pin, GPIO_MODE_INPUT);
        stm32_gpio_pull(bits[b].port, bits[b].pin, GPIO_PULL_DOWN);
    }
    TIM7->PSC = EPUCK2_APB1_TIMER_HZ / TIMER_HZ - 1u;
    TIM7->ARR = PERIOD - 1u;
    TIM7->EGR = TIM_EGR_UG; /* load the prescaler */
    TIM7->SR = 0;
    TIM7->DIER = TIM_DIER_UIE;
    TIM7->CR1 = TIM_CR1_CEN;
}
