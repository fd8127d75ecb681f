/* The e-puck2 image's board under QEMU (netduinoplus2): no clock tree to
 * wait for (QEMU models no RCC: a wait for the PLL would never end; the
 * core clock is what the machine says, 168 MHz), the console on USART1
 * (QEMU's first serial port), and exit statuses through semihosting. */
#include "openswarm/cortex_m4.h"
#include "semihosting.h"

#include <stdint.h>

#define USART1_SR (*(volatile uint32_t *)0x40011000u)
#define USART1_DR (*(volatile uint32_t *)0x40011004u)
#define USART1_CR1 (*(volatile uint32_t *)0x4001100Cu)
#define USART_SR_TXE (1u << 7)
#define USART_CR1_UE (1u << 13)
#define USART_CR1_TE (1u << 3)
#define USART_CR1_RE (1u << 2)

const uint32_t board_core_hz = 168000000u;

void board_init(void) { USART1_CR1 = USART_CR1_UE | USART_CR1_TE | USART_CR1_RE; }

void board_console_write(const char *text, uint32_t length) {
    for (uint32_t i = 0; i < length; i++) {
        while ((USART1_SR & USART_SR_TXE) == 0) {
        }
        USART1_DR = (uint8_t)text[i];
    }
}

void board_halt(int status) { semihosting_exit(status); }
