/* USART3 as the console: a ring buffer emptied on TXE. The writer and the
 * interrupt share the buffer; the writer keeps the interrupt out by
 * clearing TXEIE while it touches the buffer (a TXE interrupt already
 * pending then finds TXEIE clear and returns). Pins and speed: GCtronic's
 * firmware (board.h GPIOD_UART_TX PD8, GPIOD_UART_RX PD9; serial_comm.c
 * 115200 on SD3); PD8/PD9 are USART3's at AF7 (STM32F407 datasheet,
 * table 9). */
#include "console_usart.h"

#include <stdbool.h>

#include "stm32f4_registers.h"

#define PIN_TX 8u /* PD8 */
#define PIN_RX 9u /* PD9 */
#define AF_USART3 7u

static uint8_t buffer[EPUCK2_CONSOLE_BUFFER_BYTES];
static uint32_t head, tail; /* next to write, next to send; equal: empty */
static uint32_t lost, full_waits;

static bool is_empty(void) { return head == tail; }
static bool is_full(void) { return head - tail == EPUCK2_CONSOLE_BUFFER_BYTES; }
static void push(uint8_t byte) { buffer[head++ % EPUCK2_CONSOLE_BUFFER_BYTES] = byte; }
static uint8_t pop(void) { return buffer[tail++ % EPUCK2_CONSOLE_BUFFER_BYTES]; }

void epuck2_console_init(uint32_t apb1_hz) {
    RCC_ENABLES->AHB1ENR |= RCC_AHB1ENR_GPIODEN;
    RCC_ENABLES->APB1ENR |= RCC_APB1ENR_USART3EN;
    stm32_gpio_af(GPIOD, PIN_TX, AF_USART3);
    stm32_gpio_af(GPIOD, PIN_RX, AF_USART3);
    head = tail = lost = full_waits = 0;
    USART3->CR1 = 0;
    USART3->BRR = (apb1_hz + EPUCK2_CONSOLE_BAUD / 2u) / EPUCK2_CONSOLE_BAUD;
    USART3->CR1 = USART_CR1_UE | USART_CR1_TE; /* 8 data bits, no parity, 1 stop (CR2 0) */
}

static bool wait_for_txe(void) {
    for (uint32_t n = 0; n < EPUCK2_CONSOLE_TXE_POLLS; n++) {
        STM32_POLL();
        if (USART3->SR & USART_SR_TXE) return true;
    }
    return false;
}

/* The oldest buffered byte out by the writer itself (TXEIE clear). */
static void send_oldest(void) {
    if (wait_for_txe())
        USART3->DR = pop();
    else {
        (void)pop();
        lost++;
    }
}

void epuck2_console_write(const char *text, uint32_t length) {
    for (uint32_t i = 0; i < length; i++) {
        USART3->CR1 &= ~USART_CR1_TXEIE;
        if (is_full()) {
            full_waits++;
            send_oldest();
        }
        push((uint8_t)text[i]);
        USART3->CR1 |= USART_CR1_TXEIE;
    }
}

void epuck2_console_flush(void) {
    USART3->CR1 &= ~USART_CR1_TXEIE;
    while (!is_empty()) send_oldest();
}

uint32_t epuck2_console_lost(void) { return lost; }
uint32_t epuck2_console_full_waits(void) { return full_waits; }

void USART3_IRQHandler(void) {
    if ((USART3->CR1 & USART_CR1_TXEIE) == 0 || (USART3->SR & USART_SR_TXE) == 0) return;
    if (!is_empty()) USART3->DR = pop();
    if (is_empty()) USART3->CR1 &= ~USART_CR1_TXEIE;
}
