/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* A robot's console (GPIOR1) and debug serial port (UART0), line by line,
 * prefixed with the robot when there are several. The console also carries
 * kernel fault records (kilobot_sim.h), reported on stderr even when the
 * console is quiet: a fault is never silent. */
#include <avr_uart.h>
#include <sim_io.h>

#include "sim.h"

#define FAULT_RECORD 0x01  /* kilobot_sim.h: SIM_FAULT_RECORD */
#define THREAD_RECORD 0x02 /* kilobot_sim.h: SIM_THREAD_RECORD */

const char *kernel_fault_name(uint8_t fault) {
    switch (fault) {
    case 1: return "stack overflow"; /* SYS_FAULT_STACK_OVERFLOW */
    case 2: return "critical section left open"; /* SYS_FAULT_CRITICAL_LEAK */
    case 3: return "CPU fault"; /* SYS_FAULT_CPU (ports that trap) */
    case 4: return "an event handler ran past its limit"; /* SYS_FAULT_HANDLER_OVERRUN */
    default: return "unknown fault";
    }
}

static void put(console *c, uint8_t v) {
    if (c->quiet) return;
    if (v == '\n' || c->len == sizeof c->line - 1) {
        c->line[c->len] = '\0';
        if (c->timestamps)
            printf("%s[%10.6f s] %s\n", c->prefix, (double)c->avr->cycle / (double)c->avr->frequency,
                   c->line);
        else
            printf("%s%s\n", c->prefix, c->line);
        stdout_flush();
        c->len = 0;
    } else if (v != '\r') {
        c->line[c->len++] = (char)v;
    }
}

/* A thread record's next byte: the pid, then the name up to its 0. */
static void thread_record(console *c, uint8_t v) {
    if (c->naming == 1) {
        c->naming_pid = v;
        c->naming_len = 0;
        c->naming = 2;
        return;
    }
    char *name = c->thread_name[c->naming_pid & 0x0Fu];
    if (v == 0 || c->naming_len == sizeof c->thread_name[0] - 1) {
        name[c->naming_len] = '\0';
        c->thread_pid[c->naming_pid & 0x0Fu] = c->naming_pid;
        if (v == 0) c->naming = 0;
        return;
    }
    name[c->naming_len++] = (char)v;
}

/* " (blinker)" if the firmware named the thread with this very pid. */
static const char *thread_label(const console *c, uint8_t pid, char *out, size_t size) {
    const char *name = c->thread_name[pid & 0x0Fu];
    if (name[0] == '\0' || c->thread_pid[pid & 0x0Fu] != pid) return "";
    snprintf(out, size, " (%s)", name);
    return out;
}

static void console_write(avr_t *avr, avr_io_addr_t addr, uint8_t v, void *param) {
    console *c = param;
    avr->data[addr] = v;
    if (c->naming != 0) {
        thread_record(c, v);
    } else if (c->record_left > 0) {
        c->record[2 - c->record_left--] = v;
        if (c->record_left == 0) {
            char label[40];
            c->faults++;
            fprintf(stderr, "openswarm-sim: %skernel fault: %s in thread %u%s at %.6f s\n", c->prefix,
                    kernel_fault_name(c->record[0]), c->record[1],
                    thread_label(c, c->record[1], label, sizeof label),
                    (double)avr->cycle / (double)avr->frequency);
        }
    } else if (v == THREAD_RECORD) {
        c->naming = 1;
    } else if (v == FAULT_RECORD) {
        c->record_left = 2;
    } else {
        put(c, v);
    }
}

static void serial_output(struct avr_irq_t *irq, uint32_t value, void *param) {
    (void)irq;
    put(param, (uint8_t)value);
}

void console_attach(robot *r, int quiet, int timestamps, const char *prefix) {
    snprintf(r->console.prefix, sizeof r->console.prefix, "%s", prefix);
    snprintf(r->serial.prefix, sizeof r->serial.prefix, "%s", prefix);
    r->console.avr = r->serial.avr = r->avr;
    r->console.timestamps = r->serial.timestamps = timestamps;
    r->console.quiet = quiet;
    avr_register_io_write(r->avr, GPIOR1_ADDR, console_write, &r->console);
    if (!quiet)
        avr_irq_register_notify(avr_io_getirq(r->avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_OUTPUT),
                                serial_output, &r->serial);
}

void console_reset(robot *r) {
    r->console.record_left = 0;
    r->console.naming = 0;
}
