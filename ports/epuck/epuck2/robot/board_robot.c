/* The e-puck2's own board: the clock tree, the vector table where the
 * image is linked, the console on USART3 (the ESP32's Bluetooth serial link),
 * and a halt that stops the wheels. No semihosting: on the robot a BKPT
 * with no debugger attached is a HardFault. */
#include "openswarm/cortex_m4.h"
#include "openswarm/port.h"

#include "../drivers/clock_tree.h"
#include "../drivers/console_usart.h"
#include "../drivers/stm32f4_registers.h"
#include "board_robot.h"

#define SCB_VTOR (*(volatile uint32_t *)0xE000ED08u)

extern const void *const stm32f407_vectors[];

const uint32_t board_core_hz = EPUCK2_CORE_HZ;

/* A clock tree that did not start leaves the core on the 16 MHz internal
 * clock: the console can still say so (its baud rate from that clock),
 * and the robot stops there, since every timer would run 10 times slow. */
static void halt_for_clocks(epuck2_clock_status status) {
    epuck2_console_init(EPUCK2_HSI_HZ);
    cortex_m4_print("clock fault: ");
    cortex_m4_print(epuck2_clock_status_text(status));
    cortex_m4_print("\n");
    board_halt(4);
}

void board_init(void) {
    /* Our table, wherever the image is linked: after the Aseba bootloader,
     * which jumped here with its own table in place, or at 0x08000000,
     * where the reset found it through the boot alias at 0. */
    SCB_VTOR = (uint32_t)(uintptr_t)stm32f407_vectors;
    epuck2_clock_status clocks = epuck2_clock_tree_start();
    if (clocks != EPUCK2_CLOCKS_RUNNING) halt_for_clocks(clocks);
    epuck2_console_init(EPUCK2_APB1_HZ);
    cortex_m4_irq_enable(USART3_IRQ, ROBOT_PRIORITY_CONSOLE);
    board_outputs_start();
}

/* Threads and handlers print: masked, one writer owns the buffer. */
void board_console_write(const char *text, uint32_t length) {
    port_irq_state_t s = port_irq_save();
    epuck2_console_write(text, length);
    port_irq_restore(s);
}

/* The wheels stopped and the coils released, what was printed sent, then
 * nothing more runs: a person sees the report on the console. */
void board_halt(int status) {
    (void)status;
    __asm__ __volatile__("cpsid i" ::: "memory");
    GPIOE->BSRR = 0xFF00u << 16; /* the eight stepper coils (PE8-PE15) off */
    epuck2_console_flush();
    for (;;) __asm__ __volatile__("wfi");
}
