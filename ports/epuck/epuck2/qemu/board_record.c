#include "board_record.h"

#include "openswarm/cortex_m4.h"
#include "openswarm/port.h"
#include "openswarm/system_time.h"

#include <string.h>

#define SYST_RVR (*(volatile uint32_t *)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018u)

/* The kernel's milliseconds and SysTick's progress through the current
 * one, read together with interrupts masked. */
static uint32_t now_us(void) {
    port_irq_state_t s = port_irq_save();
    uint32_t ms = Sys_Get_SystemTime();
    uint32_t elapsed = SYST_RVR - SYST_CVR;
    port_irq_restore(s);
    return ms * 1000u + elapsed / (board_core_hz / 1000000u);
}

void board_record(const char *name, const int32_t *values, uint8_t count) {
    uint32_t us = now_us();
    port_irq_state_t s = port_irq_save(); /* one whole line among other output */
    board_console_write("\x1e", 1);
    board_console_write(name, (uint32_t)strlen(name));
    board_console_write(" ", 1);
    cortex_m4_print_uint(us);
    for (uint8_t i = 0; i < count; i++) {
        board_console_write(values[i] < 0 ? " -" : " ", values[i] < 0 ? 2u : 1u);
        cortex_m4_print_uint(values[i] < 0 ? (uint32_t)-values[i] : (uint32_t)values[i]);
    }
    board_console_write("\n", 1);
    port_irq_restore(s);
}
