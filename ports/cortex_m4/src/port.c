/* Cortex-M4 port: interrupt masking by priority (BASEPRI), the SysTick
 * 1 ms tick, sleeping idle (tickless idle: tickless_idle.c), a new thread's first frame, and the
 * interrupt epilogue's bookkeeping. The switch itself is in switch.S. */
#include "openswarm/cortex_m4.h"
#include "openswarm/port.h"
#include "system_control.h"

#include <stddef.h>

void port_thread_start(void); /* switch.S */

#define CONTROL_SPSEL 2u /* thread mode on the process stack */

/* Exception priorities once and for all (see cortex_m4.h). */
void port_init(void) {
    SCB_SHPR2 = 0x00u << 24;                    /* SVC */
    SCB_SHPR3 = (0xE0u << 24) | (0xF0u << 16); /* SysTick, PendSV */
    SCB_SHPR1 = 0;                              /* faults: the most urgent */
}

/* The initial switch frame, from the top: r4-r11 and lr as port_switch
 * pushes them, then CONTROL (no FPU context yet). */
void port_context_init(port_context_t *ctx, void *stack, size_t size, void (*entry)(void *),
                       void *arg) {
    uintptr_t top = ((uintptr_t)stack + size) & ~(uintptr_t)7u;
    uint32_t *sp = (uint32_t *)top - 10;
    sp[0] = CONTROL_SPSEL;
    for (unsigned r = 1; r <= 8; r++) sp[r] = 0; /* r4..r11 */
    sp[1] = (uint32_t)(uintptr_t)entry;          /* r4 */
    sp[2] = (uint32_t)(uintptr_t)arg;            /* r5 */
    sp[9] = (uint32_t)(uintptr_t)port_thread_start;
    ctx->sp = sp;
}

port_irq_state_t port_irq_save(void) {
    uint32_t previous;
    __asm__ __volatile__("mrs %0, basepri\n\tmsr basepri, %1"
                         : "=&r"(previous)
                         : "r"(CORTEX_M4_PRIORITY_KERNEL)
                         : "memory");
    return previous;
}

void port_irq_restore(port_irq_state_t state) {
    __asm__ __volatile__("msr basepri, %0" ::"r"(state) : "memory");
}
void port_irq_enable(void) { port_irq_restore(0); }
void port_irq_disable(void) { (void)port_irq_save(); }

void (*cortex_m4_idle_hook)(bool asleep);

/* BASEPRI-masked interrupts do not end a WFI, PRIMASK-masked ones do: so
 * PRIMASK holds them while BASEPRI opens, and no wake-up is lost between
 * the kernel's check and the sleep. The interrupt is taken at CPSIE. */
void port_idle(void) {
    void (*hook)(bool) = cortex_m4_idle_hook;
    __asm__ __volatile__("cpsid i\n\t"
                         "msr basepri, %0" ::"r"(0u)
                         : "memory");
    if (hook != NULL) hook(true);
    __asm__ __volatile__("dsb\n\t"
                         "wfi" ::: "memory");
    if (hook != NULL) hook(false);
    __asm__ __volatile__("cpsie i\n\t"
                         "isb\n\t"
                         "msr basepri, %0" ::"r"(CORTEX_M4_PRIORITY_KERNEL)
                         : "memory");
}

void port_tick_start(void) {
    SYST_RVR = board_core_hz / 1000u - 1u;
    SYST_CVR = 0;
    SYST_CSR = SYST_CSR_ENABLE | SYST_CSR_TICKINT | SYST_CSR_CLKSOURCE_CPU;
}

void (*cortex_m4_tick_hook)(void);
uint32_t cortex_m4_tick_hook_ms;

void SysTick_Handler(void) {
    cortex_m4_isr_enter();
    os_tick();
    void (*hook)(void) = cortex_m4_tick_hook;
    if (hook != NULL) hook();
    cortex_m4_isr_exit();
}

/* ---- the interrupt epilogue ----
 *
 * The first handler to end holds its nesting level (os_isr_enter's) and
 * pends PendSV; handlers that end before PendSV runs give theirs back at
 * once; the held one is given back in thread mode, where the kernel may
 * switch (cortex_m4_isr_decide, from switch.S). */
static volatile bool epilogue_pending;

void cortex_m4_isr_enter(void) {
    port_irq_state_t s = port_irq_save();
    os_isr_enter();
    port_irq_restore(s);
}

void cortex_m4_isr_exit(void) {
    port_irq_state_t s = port_irq_save();
    if (epilogue_pending) {
        os_isr_exit(); /* not the last level: nothing to decide */
    } else {
        epilogue_pending = true;
        SCB_ICSR = SCB_ICSR_PENDSVSET;
    }
    port_irq_restore(s);
}

void cortex_m4_isr_decide(void); /* called from switch.S only */
void cortex_m4_isr_decide(void) {
    epilogue_pending = false;
    os_isr_exit();
}

void cortex_m4_irq_enable(int irq, uint8_t priority) {
    NVIC_IPR8(irq) = priority;
    NVIC_ISER((unsigned)irq / 32u) = 1u << ((unsigned)irq % 32u);
}

void cortex_m4_irq_disable(int irq) {
    NVIC_ICER((unsigned)irq / 32u) = 1u << ((unsigned)irq % 32u);
}
