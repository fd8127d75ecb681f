/* What a Kilobot firmware tells the simulator (sim/openswarm-sim): a
 * console, kernel faults and an exit status, through two general-purpose
 * I/O registers that the real robot ignores. */
#ifndef OPENSWARM_KILOBOT_SIM_H
#define OPENSWARM_KILOBOT_SIM_H

#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/pgmspace.h>
#include <avr/sleep.h>

/* One console character (a line ends with '\n'). */
static inline void sim_putc(char c) { GPIOR1 = (uint8_t)c; }

static inline void sim_puts_P(const char *flash) {
    char c;
    while ((c = (char)pgm_read_byte(flash++)) != '\0') sim_putc(c);
}

static inline void sim_put_uint(uint32_t v) {
    char digits[10];
    uint8_t n = 0;
    do {
        digits[n++] = (char)('0' + v % 10u);
        v /= 10u;
    } while (v != 0);
    while (n != 0) sim_putc(digits[--n]);
}

/* A kernel fault (a sys_fault and the thread's pid): the simulator prints
 * "kernel fault: stack overflow in thread 19" on its standard error. */
#define SIM_FAULT_RECORD 0x01
static inline void sim_fault(uint8_t fault, uint8_t pid) {
    GPIOR1 = SIM_FAULT_RECORD;
    GPIOR1 = fault;
    GPIOR1 = pid;
}

/* A thread's name (in flash), so the simulator can name it in a fault
 * report: "kernel fault: stack overflow in thread 1 (blinker)". The
 * generated start-up code (openswarm.json's threads) and kilolib call it. */
#define SIM_THREAD_RECORD 0x02
static inline void sim_thread_name(uint8_t pid, const char *name) {
    GPIOR1 = SIM_THREAD_RECORD;
    GPIOR1 = pid;
    char c;
    do {
        c = (char)pgm_read_byte(name++);
        GPIOR1 = (uint8_t)c;
    } while (c != '\0');
}

/* Stop the simulation with an exit status (the real robot just halts). */
static inline void sim_exit(uint8_t status) {
    GPIOR0 = status;
    cli();
    sleep_enable();
    for (;;) sleep_cpu();
}

#endif
