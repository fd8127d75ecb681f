/* The e-puck2's IR proximity sensors. TIM2 counts at 1 MHz with a period
 * of 1250 us (800 Hz): 8 periods a round, two per pair of sensors (IR0 with
 * IR4, IR1-IR5, IR2-IR6, IR3-IR7: opposite ones, which see each other's
 * emitters least), first with the emitters off (ambient), then with the
 * pair's emitters pulsed for the first 300 us. At 260 us of every period
 * (compare 2) ADC2 converts the pair's two channels, so a pulsed sample is
 * taken while the pulse still shines; compare 1 ends the pulse. After the
 * eighth period's conversions the round goes to on_round. Facts and their
 * sources: ports/epuck/README.md. */
#include "proximity.h"

#include "stm32f4_registers.h"

#define TIMER_HZ 1000000u
#define PERIOD_US 1250u
#define PULSE_US 300u
#define SAMPLE_AT_US 260u

/* Each pair's ADC channels (sensor a, sensor a + 4) and emitter pin. */
static const struct {
    uint8_t channel[2];
    stm32_gpio *pulse_port;
    uint8_t pulse_pin;
} pairs[4] = {
    {{12, 9}, GPIOB, 12},  /* IR0 PC2, IR4 PB1; pulse PB12 */
    {{13, 8}, GPIOB, 14},  /* IR1 PC3, IR5 PB0; pulse PB14 */
    {{14, 10}, GPIOE, 2},  /* IR2 PC4, IR6 PC0; pulse PE2 */
    {{15, 11}, GPIOE, 3},  /* IR3 PC5, IR7 PC1; pulse PE3 */
};

static epuck2_proximity_round round_done;
static epuck_proximity_samples samples;
static uint8_t period;     /* 0..7 of the round: pair period / 2, pulsed if odd */
static uint8_t conversion; /* 0 or 1: which of the pair's channels */

/* One BSRR write a port: every emitter off at once. */
static void pulses_off(void) {
    uint32_t on_b = 0, on_e = 0;
    for (unsigned p = 0; p < 4; p++) {
        if (pairs[p].pulse_port == GPIOB)
            on_b |= 1u << pairs[p].pulse_pin;
        else
            on_e |= 1u << pairs[p].pulse_pin;
    }
    GPIOB->BSRR = on_b << 16;
    GPIOE->BSRR = on_e << 16;
}

static void convert_pair(void) {
    unsigned pair = period / 2u;
    conversion = 0;
    ADC2->SQR3 = pairs[pair].channel[0] | ((uint32_t)pairs[pair].channel[1] << 5);
    ADC2->CR2 |= ADC_CR2_SWSTART;
}

/* The flags it finds are cleared in one write (rc_w0: zeros clear, ones
 * leave alone), so none that rises meanwhile is lost. */
void TIM2_IRQHandler(void) {
    uint32_t sr = TIM2->SR & (TIM_SR_UIF | TIM_SR_CC1IF | TIM_SR_CC2IF);
    TIM2->SR = ~sr;
    if (sr & TIM_SR_UIF) { /* a new period */
        period = (uint8_t)((period + 1u) & 7u);
        if (period & 1u) pairs[period / 2u].pulse_port->BSRR = 1u << pairs[period / 2u].pulse_pin;
    }
    if (sr & TIM_SR_CC2IF) convert_pair(); /* 260 us: sample */
    if (sr & TIM_SR_CC1IF) pulses_off();   /* 300 us: the pulse ends */
}

void ADC_IRQHandler(void) {
    if ((ADC2->SR & ADC_SR_EOC) == 0) return;
    uint16_t value = (uint16_t)(ADC2->DR & 0x0FFFu); /* reading DR clears EOC */
    unsigned sensor = period / 2u + 4u * conversion;
    if (period & 1u)
        samples.pulsed[sensor] = value;
    else
        samples.off[sensor] = value;
    if (++conversion < 2u) return;
    if (period == 7u && round_done != 0) round_done(&samples);
}

void epuck2_proximity_init(epuck2_proximity_round on_round) {
    round_done = on_round;
    period = 7; /* the first update starts period 0 */
    RCC_ENABLES->AHB1ENR |= RCC_AHB1ENR_GPIOBEN | RCC_AHB1ENR_GPIOCEN | RCC_AHB1ENR_GPIOEEN;
    RCC_ENABLES->APB1ENR |= RCC_APB1ENR_TIM2EN;
    RCC_ENABLES->APB2ENR |= RCC_APB2ENR_ADC2EN;
    for (unsigned pin = 0; pin <= 5; pin++) stm32_gpio_mode(GPIOC, pin, GPIO_MODE_ANALOG);
    stm32_gpio_mode(GPIOB, 0, GPIO_MODE_ANALOG);
    stm32_gpio_mode(GPIOB, 1, GPIO_MODE_ANALOG);
    for (unsigned p = 0; p < 4; p++) stm32_gpio_mode(pairs[p].pulse_port, pairs[p].pulse_pin, GPIO_MODE_OUTPUT);
    pulses_off();
    /* ADC2: 12 bits, the pair's two channels in one scan, an interrupt at
     * each conversion's end, 112 sampling cycles at 10.5 MHz (84 / 8): about
     * 12 us a channel, both done long before the pulse ends. */
    ADC_COMMON_CCR = ADC_CCR_ADCPRE_DIV8;
    ADC2->SMPR1 = 0;
    ADC2->SMPR2 = 0;
    for (unsigned ch = 8; ch <= 15; ch++) {
        if (ch <= 9)
            ADC2->SMPR2 |= ADC_SAMPLE_112_CYCLES << (3u * ch);
        else
            ADC2->SMPR1 |= ADC_SAMPLE_112_CYCLES << (3u * (ch - 10u));
    }
    ADC2->SQR1 = 1u << 20; /* two conversions (L = 1) */
    ADC2->CR1 = ADC_CR1_SCAN | ADC_CR1_EOCIE;
    ADC2->CR2 = ADC_CR2_EOCS | ADC_CR2_ADON;
    TIM2->PSC = EPUCK2_APB1_TIMER_HZ / TIMER_HZ - 1u;
    TIM2->ARR = PERIOD_US - 1u;
    TIM2->CCR[0] = PULSE_US;
    TIM2->CCR[1] = SAMPLE_AT_US;
    TIM2->EGR = TIM_EGR_UG;
    TIM2->SR = 0;
    TIM2->DIER = TIM_DIER_UIE | TIM_DIER_CC1IE | TIM_DIER_CC2IE;
    TIM2->CR1 = TIM_CR1_CEN;
}
