/* The robot's console in the native mode: what the firmware tells the
 * simulator (kilobot_sim.h) and its debug serial port (printf after
 * kilobot_console_init or debug_init, as on the robot: before, stdout goes
 * nowhere). Text goes to the robot's console in its native_io; the
 * simulator prints it line by line. Each character on the serial port
 * costs the 260 us it takes at 38400 baud, as printf's busy wait does on
 * the robot. printf, puts and putchar are the robot's own here: the
 * shared object binds its calls to them, not to the host's. */
#include "native_internal.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "debug.h"
#include "openswarm/kilobot.h"
#include "openswarm/kilobot_sim.h"

#define SERIAL_CHARACTER_CYCLES 2083u /* 10 bits at 38400 baud, 8 MHz */

static uint8_t serial_ready;

void sim_putc(char c) {
    native_io *io = native_io_of_robot;
    while (io->console_len >= NATIVE_CONSOLE_ROOM) native_yield(); /* the simulator prints it */
    io->console[io->console_len++] = c;
}

void sim_puts_P(const char *text) {
    while (*text != '\0') sim_putc(*text++);
}

void sim_put_uint(uint32_t v) {
    char digits[11];
    snprintf(digits, sizeof digits, "%lu", (unsigned long)v);
    sim_puts_P(digits);
}

void sim_fault(uint8_t fault, uint8_t pid) { port_report_fault(fault, pid); }

void sim_thread_name(uint8_t pid, const char *name) {
    char *slot = native_io_of_robot->thread_name[pid % NATIVE_THREAD_NAMES];
    strncpy(slot, name, sizeof native_io_of_robot->thread_name[0] - 1);
}

void sim_exit(uint8_t status) { native_stop(status); }

void kilobot_console_init(void) { serial_ready = 1; }
void debug_init(void) { kilobot_console_init(); }

static void serial_put(const char *text, size_t n) {
    if (!serial_ready) return;
    for (size_t i = 0; i < n; i++) {
        native_wait_for_hardware(SERIAL_CHARACTER_CYCLES);
        sim_putc(text[i]);
    }
}

int vprintf(const char *format, va_list args) {
    char line[256];
    va_list again;
    va_copy(again, args);
    int n = vsnprintf(line, sizeof line, format, args);
    if (n >= (int)sizeof line) { /* rare: long text goes out in full */
        char long_text[n + 1];
        vsnprintf(long_text, sizeof long_text, format, again);
        serial_put(long_text, (size_t)n);
    } else if (n > 0) {
        serial_put(line, (size_t)n);
    }
    va_end(again);
    return serial_ready ? n : -1;
}

int printf(const char *format, ...) {
    va_list args;
    va_start(args, format);
    int n = vprintf(format, args);
    va_end(args);
    return n;
}

int puts(const char *text) {
    serial_put(text, strlen(text));
    serial_put("\n", 1);
    return serial_ready ? 1 : EOF;
}

int putchar(int c) {
    char ch = (char)c;
    serial_put(&ch, 1);
    return serial_ready ? (unsigned char)c : EOF;
}
