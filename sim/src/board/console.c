/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* A robot's console (GPIOR1) and debug serial port (UART0), line by line,
 * prefixed with the robot when there are several; with --console-csv also
 * into a file, time_s,robot,line (even when quiet). The console also carries
 * kernel fault records (kilobot_sim.h), reported on stderr even when the
 * console is quiet: a fault is never silent. */
#include <avr_uart.h>
#include <errno.h>
#include <sim_io.h>
#include <stdlib.h>
#include <string.h>

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

/* One CSV row: the line quoted, its quotes doubled. */
static int format_row(char *out, size_t size, double time_s, int index, const char *line) {
    int n = snprintf(out, size, "%.6f,%d,\"", time_s, index);
    for (const char *p = line; *p && n + 4 < (int)size; p++) {
        if (*p == '"') out[n++] = '"';
        out[n++] = *p;
    }
    out[n++] = '"';
    out[n++] = '\n';
    out[n] = '\0';
    return n;
}

/* The row joins the robot's others until the window ends. */
static void keep_row(console_rows *rows, double time_s, int index, const char *line) {
    char row[2 * sizeof ((console *)0)->line + 40];
    int n = format_row(row, sizeof row, time_s, index, line);
    if (rows->len + (size_t)n + 1 > rows->room) {
        size_t room = rows->room ? 2 * rows->room : 1024;
        while (room < rows->len + (size_t)n + 1) room *= 2;
        char *text = realloc(rows->text, room);
        if (text == NULL) {
            rows->failed = 1;
            return;
        }
        rows->text = text;
        rows->room = room;
    }
    memcpy(rows->text + rows->len, row, (size_t)n + 1);
    rows->len += (size_t)n;
}

/* A character from an interrupt handler lands in the middle of whatever
 * line a thread is printing: counted, for the warning at the end. simavr
 * keeps the stack of interrupts being served (RETI pops it). */
static void note_interrupt_context(console *c) {
    if (c->avr->interrupts.running_ptr == 0) return;
    if (c->from_interrupt++ == 0)
        c->from_interrupt_at = (double)c->avr->cycle / (double)c->avr->frequency;
}

static void put(console *c, uint8_t v) {
    note_interrupt_context(c);
    if (c->quiet && c->rows == NULL) return;
    if (v == '\n' || c->len == sizeof c->line - 1) {
        c->line[c->len] = '\0';
        double t = (double)c->avr->cycle / (double)c->avr->frequency;
        if (!c->quiet) {
            if (c->timestamps)
                printf("%s[%10.6f s] %s\n", c->prefix, t, c->line);
            else
                printf("%s%s\n", c->prefix, c->line);
            stdout_flush();
        }
        if (c->rows != NULL) keep_row(c->rows, t, c->index, c->line);
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

/* A handler past its limit is reported by the tick with the system
 * thread's pid, which runs every handler: "thread 0" would point at the
 * kernel. The handler is named once the tick has returned into it
 * (fault_place_after_window). */
static void report_fault(console *c) {
    char label[40];
    double t = (double)c->avr->cycle / (double)c->avr->frequency;
    c->faults++;
    if (c->record[0] == 4) { /* SYS_FAULT_HANDLER_OVERRUN */
        fprintf(stderr, "openswarm-sim: %skernel fault: %s at %.6f s\n", c->prefix,
                kernel_fault_name(c->record[0]), t);
        c->overrun_pending = 1;
        return;
    }
    fprintf(stderr, "openswarm-sim: %skernel fault: %s in thread %u%s at %.6f s%s\n", c->prefix,
            kernel_fault_name(c->record[0]), c->record[1], thread_label(c, c->record[1], label, sizeof label),
            t, c->record[0] == 1 ? ": give the thread a bigger \"stack\" in openswarm.json" : "");
}

static void console_write(avr_t *avr, avr_io_addr_t addr, uint8_t v, void *param) {
    console *c = param;
    avr->data[addr] = v;
    if (c->naming != 0) {
        thread_record(c, v);
    } else if (c->record_left > 0) {
        c->record[2 - c->record_left--] = v;
        if (c->record_left == 0) report_fault(c);
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

void console_attach(robot *r, int quiet, int timestamps, const char *prefix, int csv) {
    snprintf(r->console.prefix, sizeof r->console.prefix, "%s", prefix);
    snprintf(r->serial.prefix, sizeof r->serial.prefix, "%s", prefix);
    r->console.avr = r->serial.avr = r->avr;
    r->console.index = r->serial.index = r->index;
    r->console.timestamps = r->serial.timestamps = timestamps;
    r->console.quiet = r->serial.quiet = quiet;
    r->console.rows = r->serial.rows = csv ? &r->console_rows : NULL;
    avr_register_io_write(r->avr, GPIOR1_ADDR, console_write, &r->console);
    if (!quiet || csv)
        avr_irq_register_notify(avr_io_getirq(r->avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_OUTPUT),
                                serial_output, &r->serial);
}

void console_reset(robot *r) {
    r->console.record_left = 0;
    r->console.naming = 0;
}

FILE *console_csv_open(const char *path) {
    FILE *f = fopen(path, "w");
    if (f == NULL) {
        fprintf(stderr, "openswarm-sim: --console-csv %s: %s; give a file in a folder that exists "
                        "and can be written\n", path, strerror(errno));
        return NULL;
    }
    fprintf(f, "time_s,robot,line\n");
    return f;
}

void console_csv_row(FILE *f, double time_s, int index, const char *line) {
    char row[2 * sizeof ((console *)0)->line + 40];
    format_row(row, sizeof row, time_s, index, line);
    fputs(row, f);
}

void console_csv_write(FILE *f, robot *robots, int n) {
    for (int i = 0; i < n; i++) {
        console_rows *rows = &robots[i].console_rows;
        if (rows->len == 0) continue;
        fwrite(rows->text, 1, rows->len, f);
        rows->len = 0;
    }
}

int console_csv_close(FILE *f, const char *path, robot *robots, int n) {
    int lost = 0;
    if (robots != NULL) {
        console_csv_write(f, robots, n);
        for (int i = 0; i < n; i++) {
            lost |= robots[i].console_rows.failed;
            free(robots[i].console_rows.text);
            memset(&robots[i].console_rows, 0, sizeof robots[i].console_rows);
        }
    }
    int bad = ferror(f);
    if (fclose(f) != 0 || bad) {
        fprintf(stderr, "openswarm-sim: cannot write %s: %s; is the disk full?\n", path, strerror(errno));
        return -1;
    }
    if (lost) {
        fprintf(stderr, "openswarm-sim: out of memory keeping console lines for %s: some are "
                        "missing from it\n", path);
        return -1;
    }
    return 0;
}
