/* The firmware suites' target on the e-puck2 image under QEMU: the
 * board's console (USART1), TIM2 for interrupts, and the exit status
 * through semihosting.
 *
 * QEMU 7.2's STM32 timers count at 1 GHz of virtual time whatever RCC
 * says (with -icount, exactly), and a timer started at time T first
 * updates at 2T + its period, then every period. So TIM2 is started once
 * at boot, ticking every 50 us, and an interrupt "in us microseconds" is
 * a countdown of its updates. */
#include "test_target.h"

#include "openswarm/cortex_m4.h"

#define TIM2_BASE 0x40000000u
#define TIM_REG(offset) (*(volatile uint32_t *)(TIM2_BASE + (offset)))
#define TIM_CR1 TIM_REG(0x00u)
#define TIM_DIER TIM_REG(0x0Cu)
#define TIM_SR TIM_REG(0x10u)
#define TIM_CNT TIM_REG(0x24u)
#define TIM_PSC TIM_REG(0x28u)
#define TIM_ARR TIM_REG(0x2Cu)
#define TIM_CR1_CEN (1u << 0)
#define TIM_DIER_UIE (1u << 0)
#define TIM2_IRQ 28
#define QEMU_TIMER_HZ 1000000000u
#define UPDATE_US 50u

void target_init(void) {
    TIM_PSC = QEMU_TIMER_HZ / 1000000u - 1u; /* 1 us a count */
    TIM_SR = 0;
    TIM_DIER = TIM_DIER_UIE;
    TIM_CR1 = TIM_CR1_CEN;
    TIM_CNT = 0;
    TIM_ARR = UPDATE_US; /* QEMU schedules the update when ARR is written */
    cortex_m4_irq_enable(TIM2_IRQ, CORTEX_M4_PRIORITY_DEVICE);
}

void target_puts(const char *text) { cortex_m4_print(text); }
void target_putc(char c) { board_console_write(&c, 1); }

void target_put_uint(uint32_t value) { cortex_m4_print_uint(value); }

void target_exit(uint8_t status) { board_halt(status); }

static volatile int16_t pending_value;
static volatile uint16_t updates_left; /* 0: nothing armed */

void target_interrupt_in(uint16_t us, int16_t value) {
    pending_value = value;
    updates_left = (uint16_t)(us / UPDATE_US != 0 ? us / UPDATE_US : 1u);
}

/* Kernel-aware only on the update that fires. */
void TIM2_IRQHandler(void) {
    TIM_SR = 0;
    if (updates_left == 0 || --updates_left != 0) return;
    cortex_m4_isr_enter();
    target_interrupt(pending_value);
    cortex_m4_isr_exit();
}
