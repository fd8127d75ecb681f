/* The e-puck2's steppers. Each motor has four coil inputs on GPIOE (right:
 * IN1 PE13, IN2 PE12, IN3 PE14, IN4 PE15; left: IN1 PE9, IN2 PE8, IN3
 * PE11, IN4 PE10) and is driven in half steps: 8 coil patterns a cycle, two
 * per motor step, one per update of its timer (right TIM3, left TIM4),
 * which counts at 100 kHz; so a speed of s steps/s is an update every
 * 100000 / (2 s) counts. The motors face each other: forward is the pattern
 * sequence backwards on the right, forwards on the left. Stopped, the
 * coils are off (no current held) and the timer updates at 100 Hz. Facts:
 * ports/epuck/README.md. The update interrupts call nothing of the kernel:
 * they run above its mask (CORTEX_M4_PRIORITY_UNMASKED), on time. */
#include "steppers.h"

#include "stm32f4_registers.h"

#define TIMER_HZ 100000u
#define HALTED_PERIOD 1000u /* counts: 100 Hz */

/* Half-step coil patterns, bits IN1..IN4. */
static const uint8_t half_steps[8] = {0x5, 0x4, 0x6, 0x2, 0xA, 0x8, 0x9, 0x1};

typedef struct stepper {
    stm32_timer *timer;
    uint8_t pins[4]; /* GPIOE pin of IN1..IN4 */
    int8_t forward;  /* +1 or -1: the pattern index's way for forward */
    volatile int8_t direction; /* -1, 0, +1 */
    uint8_t index;
    volatile int32_t half_steps_made;
} stepper;

static stepper motors[2] = {
    {TIM4, {9, 8, 11, 10}, +1, 0, 0, 0},  /* left */
    {TIM3, {13, 12, 14, 15}, -1, 0, 0, 0}, /* right */
};

/* One BSRR write: each coil's pin set or reset at once. */
static void drive(const stepper *m, uint8_t coils) {
    uint32_t set = 0, reset = 0;
    for (unsigned i = 0; i < 4; i++) {
        if (coils & (1u << i))
            set |= 1u << m->pins[i];
        else
            reset |= 1u << m->pins[i];
    }
    GPIOE->BSRR = set | (reset << 16);
}

static void step(stepper *m) {
    m->timer->SR = ~TIM_SR_UIF; /* rc_w0: clears the update flag alone */
    if (m->direction == 0) {
        drive(m, 0);
        return;
    }
    m->index = (uint8_t)((unsigned)(m->index + m->direction * m->forward) & 7u);
    m->half_steps_made += m->direction;
    drive(m, half_steps[m->index]);
}

void TIM3_IRQHandler(void) { step(&motors[1]); }
void TIM4_IRQHandler(void) { step(&motors[0]); }

static void set_speed(stepper *m, int16_t steps_per_s) {
    uint32_t speed = (uint32_t)(steps_per_s < 0 ? -steps_per_s : steps_per_s);
    m->direction = (int8_t)(steps_per_s > 0 ? 1 : steps_per_s < 0 ? -1 : 0);
    /* ARR is preloaded (ARPE): the new period starts at the next update. */
    m->timer->ARR = speed == 0 ? HALTED_PERIOD - 1u : TIMER_HZ / (2u * speed) - 1u;
}

void epuck2_steppers_set(int16_t left, int16_t right) {
    set_speed(&motors[0], left);
    set_speed(&motors[1], right);
}

int32_t epuck2_steppers_position(int side) { return motors[side != 0].half_steps_made / 2; }

void epuck2_steppers_init(void) {
    RCC_ENABLES->AHB1ENR |= RCC_AHB1ENR_GPIOEEN;
    RCC_ENABLES->APB1ENR |= RCC_APB1ENR_TIM3EN | RCC_APB1ENR_TIM4EN;
    for (unsigned side = 0; side < 2; side++) {
        stepper *m = &motors[side];
        for (unsigned i = 0; i < 4; i++) stm32_gpio_mode(GPIOE, m->pins[i], GPIO_MODE_OUTPUT);
        drive(m, 0);
        m->direction = 0;
        m->index = 0;
        m->half_steps_made = 0;
        m->timer->PSC = EPUCK2_APB1_TIMER_HZ / TIMER_HZ - 1u;
        m->timer->ARR = HALTED_PERIOD - 1u;
        m->timer->EGR = TIM_EGR_UG; /* load the prescaler */
        m->timer->SR = 0;
        m->timer->DIER = TIM_DIER_UIE;
        m->timer->CR1 = TIM_CR1_ARPE | TIM_CR1_CEN;
    }
}
