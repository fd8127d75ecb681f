/* The e-puck2 image's board under QEMU (netduinoplus2): no clock tree to
 * wait for (QEMU models no RCC: a wait for the PLL would never end; the
 * core clock is what the machine says, 168 MHz), the console on USART1
 * (QEMU's first serial port), exit statuses through semihosting, and an
 * end to the run (and the robot's id, --id=N): given --stop-ms=N among QEMU's semihosting arguments,
 * the board exits (status 0) when the kernel's clock reaches N ms, so a
 * run lasts the same simulated time on any machine. */
#include "openswarm/cortex_m4.h"
#include "openswarm/fault.h"
#include "openswarm/system_time.h"
#include "board_qemu.h"
#include "board_record.h"
#include "semihosting.h"

#include <stddef.h>
#include <stdint.h>
#include <string.h>

#define USART1_SR (*(volatile uint32_t *)0x40011000u)
#define USART1_DR (*(volatile uint32_t *)0x40011004u)
#define USART1_CR1 (*(volatile uint32_t *)0x4001100Cu)
#define USART_SR_TXE (1u << 7)
#define USART_CR1_UE (1u << 13)
#define USART_CR1_TE (1u << 3)
#define USART_CR1_RE (1u << 2)

const uint32_t board_core_hz = 168000000u;

/* sys_stats' uint16_t counters, before its queue's peak byte. */
#define KERNEL_LOSS_COUNTERS 12
_Static_assert(offsetof(sys_stats, event_queue_peak) == KERNEL_LOSS_COUNTERS * sizeof(uint16_t),
               "sys_stats begins with its counters");

static uint32_t stop_ms;
uint8_t board_selector_position;
uint16_t board_robot_id;

/* The kernel's loss counters (sys_stats, in order), which the runner
 * turns into the warnings at the end of the run: what the firmware lost
 * or was refused without failing. */
static void record_losses(void) {
    sys_stats stats;
    Sys_Get_Stats(&stats);
    uint16_t counters[KERNEL_LOSS_COUNTERS];
    memcpy(counters, &stats, sizeof counters); /* sys_stats begins with them, in order */
    int32_t values[KERNEL_LOSS_COUNTERS];
    for (unsigned i = 0; i < KERNEL_LOSS_COUNTERS; i++) values[i] = counters[i];
    board_record("losses", values, KERNEL_LOSS_COUNTERS);
}

/* The "stop" record tells the runner the run reached its end (status 0
 * alone could also be main returning 0, or a debugger ending QEMU). */
static void stop_when_due(void) {
    if (Sys_Get_SystemTime() < stop_ms) return;
    record_losses();
    board_record("stop", NULL, 0);
    semihosting_exit(0);
}

/* key (such as "--stop-ms=") and its digits, anywhere in the line; 0 if
 * absent. */
static uint32_t number_given(const char *line, const char *key) {
    const char *at = strstr(line, key);
    uint32_t n = 0;
    if (at == NULL) return 0;
    for (at += strlen(key); *at >= '0' && *at <= '9'; at++) n = n * 10u + (uint32_t)(*at - '0');
    return n;
}

void board_init(void) {
    USART1_CR1 = USART_CR1_UE | USART_CR1_TE | USART_CR1_RE;
    char line[128];
    if (semihosting_command_line(line, sizeof line)) {
        stop_ms = number_given(line, "--stop-ms=");
        board_selector_position = (uint8_t)(number_given(line, "--selector=") & 0x0Fu);
        board_robot_id = (uint16_t)number_given(line, "--id=");
    }
    if (stop_ms != 0) {
        cortex_m4_tick_hook = stop_when_due;
        cortex_m4_tick_hook_ms = stop_ms; /* tickless idle wakes then at the latest */
    }
}

void board_console_write(const char *text, uint32_t length) {
    for (uint32_t i = 0; i < length; i++) {
        while ((USART1_SR & USART_SR_TXE) == 0) {
        }
        USART1_DR = (uint8_t)text[i];
    }
}

void board_halt(int status) { semihosting_exit(status); }
