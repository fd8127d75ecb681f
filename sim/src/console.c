/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* A robot's console (GPIOR1) and debug serial port (UART0), line by line,
 * prefixed with the robot when there are several. */
#include <avr_uart.h>
#include <sim_io.h>

#include "sim.h"

static void put(console *c, uint8_t v) {
    if (v == '\n' || c->len == sizeof c->line - 1) {
        c->line[c->len] = '\0';
        printf("%s%s\n", c->prefix, c->line);
        fflush(stdout);
        c->len = 0;
    } else if (v != '\r') {
        c->line[c->len++] = (char)v;
    }
}

static void console_write(avr_t *avr, avr_io_addr_t addr, uint8_t v, void *param) {
    avr->data[addr] = v;
    put(param, v);
}

static void console_drop(avr_t *avr, avr_io_addr_t addr, uint8_t v, void *param) {
    (void)param;
    avr->data[addr] = v;
}

static void serial_output(struct avr_irq_t *irq, uint32_t value, void *param) {
    (void)irq;
    put(param, (uint8_t)value);
}

void console_attach(robot *r, int quiet, const char *prefix) {
    snprintf(r->console.prefix, sizeof r->console.prefix, "%s", prefix);
    snprintf(r->serial.prefix, sizeof r->serial.prefix, "%s", prefix);
    avr_register_io_write(r->avr, GPIOR1_ADDR, quiet ? console_drop : console_write, &r->console);
    if (!quiet)
        avr_irq_register_notify(avr_io_getirq(r->avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_OUTPUT),
                                serial_output, &r->serial);
}
