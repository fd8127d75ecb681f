#include "leds.h"

#include "stm32f4_registers.h"

#define PIN_BODY 2u   /* PB2 */
#define PIN_FRONT 14u /* PD14 */
static const uint8_t red_ring_pins[4] = {5u, 6u, 10u, 11u}; /* LED1, 3, 5, 7 on GPIOD */

void epuck2_leds_init(void) {
    RCC_ENABLES->AHB1ENR |= RCC_AHB1ENR_GPIOBEN | RCC_AHB1ENR_GPIODEN;
    /* Off before they are outputs: GPIOD's in one write (ring high, front low). */
    uint32_t ring = 0;
    for (unsigned i = 0; i < 4u; i++) ring |= 1u << red_ring_pins[i];
    GPIOD->BSRR = ring | (1u << (PIN_FRONT + 16u));
    GPIOB->BSRR = 1u << (PIN_BODY + 16u);
    for (unsigned i = 0; i < 4u; i++) stm32_gpio_mode(GPIOD, red_ring_pins[i], GPIO_MODE_OUTPUT);
    stm32_gpio_mode(GPIOB, PIN_BODY, GPIO_MODE_OUTPUT);
    stm32_gpio_mode(GPIOD, PIN_FRONT, GPIO_MODE_OUTPUT);
}

void epuck2_leds_set_ring(uint8_t mask) {
    uint32_t set = 0, reset = 0;
    for (unsigned i = 0; i < 4u; i++) {
        uint32_t pin = 1u << red_ring_pins[i];
        if (mask & (1u << (2u * i)))
            reset |= pin; /* lit: low */
        else
            set |= pin;
    }
    GPIOD->BSRR = set | (reset << 16);
}

void epuck2_leds_set_body(bool on) { GPIOB->BSRR = on ? 1u << PIN_BODY : 1u << (PIN_BODY + 16u); }

void epuck2_leds_set_front(bool on) { GPIOD->BSRR = on ? 1u << PIN_FRONT : 1u << (PIN_FRONT + 16u); }
