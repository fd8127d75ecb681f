#include "cpu_account.h"

#include <stdbool.h>

#include "openswarm/config.h"
#include "openswarm/cortex_m4.h"

#define TIM2_CR1 (*(volatile uint32_t *)0x40000000u)
#define TIM2_CNT (*(volatile uint32_t *)0x40000024u)
#define TIM2_PSC (*(volatile uint32_t *)0x40000028u)
#define TIM2_ARR (*(volatile uint32_t *)0x4000002Cu)

/* 64-bit sums: TIM2 wraps every 4.3 s; the sums are brought up to date
 * at every interval's end, far more often than that. */
static uint64_t total_ns, spent_ns[CPU_KINDS];
static uint32_t last_read, asleep_since;

uint32_t cpu_account_now(void) {
    uint32_t now = TIM2_CNT;
    total_ns += (uint32_t)(now - last_read);
    last_read = now;
    return now;
}

void cpu_account_add(cpu_account_kind kind, uint32_t since) {
    spent_ns[kind] += (uint32_t)(cpu_account_now() - since);
}

static void idle(bool asleep) {
    if (asleep) asleep_since = cpu_account_now();
    else cpu_account_add(CPU_ASLEEP, asleep_since);
}

void cpu_account_start(void) {
    TIM2_PSC = 0; /* a count a nanosecond */
    TIM2_CR1 = 1;
    TIM2_ARR = 0xFFFFFFFFu; /* QEMU schedules the counter when ARR is written */
    last_read = TIM2_CNT;
    cortex_m4_idle_hook = idle;
}

static void print_us(const char *label, uint64_t ns) {
    cortex_m4_print(label);
    cortex_m4_print_uint((uint32_t)(ns / 1000u));
    cortex_m4_print(" us");
}

/* Microseconds fit 32 bits for runs under 71 minutes of virtual time. */
void cpu_account_report(bool kernel_ran) {
    cpu_account_now();
    uint64_t robot = total_ns - spent_ns[CPU_LINK];
    uint64_t busy = robot - spent_ns[CPU_ASLEEP];
    print_us("cpu account: robot time ", robot);
    print_us(", asleep ", spent_ns[CPU_ASLEEP]);
    print_us(", sensors ", spent_ns[CPU_SENSORS]);
    print_us(", other busy ", busy - spent_ns[CPU_SENSORS]);
    print_us(", link (not the robot's) ", spent_ns[CPU_LINK]);
    cortex_m4_print(", tick ");
    cortex_m4_print(!kernel_ran ? "none" : OS_CFG_TICKLESS ? "tickless idle" : "periodic");
    cortex_m4_print("\n");
}
