/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* Where a program counter is in the app's sources, for the reports that
 * name code (a handler past its limit, a crash): avr-addr2line (binutils-
 * avr, which builds the firmware anyway) reads the ELF's debug lines. A
 * firmware built without them, or a missing tool, gives the PC alone. A
 * native robot's shared object is read the same way by the host's
 * addr2line (binutils, which the host compiler needs). */
#include <stdlib.h>
#include <string.h>

#include "sim.h"

/* path in single quotes for the shell, its own quotes escaped. */
static void shell_quote(const char *path, char *out, size_t size) {
    size_t n = 0;
    out[n++] = '\'';
    for (const char *p = path; *p && n + 5 < size; p++) {
        if (*p == '\'') {
            memcpy(out + n, "'\\''", 4);
            n += 4;
        } else {
            out[n++] = *p;
        }
    }
    out[n++] = '\'';
    out[n] = '\0';
}

static void chomp(char *s) {
    s[strcspn(s, "\r\n")] = '\0';
}

/* "main.c:17"; not "??:?", nor ":?" (a file without line numbers: an
 * image built without -g, as release images are). */
static int known_line(const char *line) {
    size_t n = strlen(line);
    return n > 2 && line[0] != ':' && strncmp(line, "??", 2) != 0 && strcmp(line + n - 2, ":?") != 0 &&
           strcmp(line + n - 2, ":0") != 0;
}

/* tool's (an addr2line) function and source line of address in file;
 * either empty when it cannot tell. */
static void addr2line(const char *tool, const char *file, uint64_t address, char *function, size_t function_size,
                      char *line, size_t line_size) {
    char quoted[4200], command[4400];
    function[0] = line[0] = '\0';
    shell_quote(file, quoted, sizeof quoted);
    snprintf(command, sizeof command, "%s -f -C -s -e %s 0x%llx 2>/dev/null", tool, quoted,
             (unsigned long long)address);
    FILE *p = popen(command, "r");
    if (p == NULL) return;
    if (fgets(function, (int)function_size, p) != NULL) chomp(function);
    if (fgets(line, (int)line_size, p) != NULL) chomp(line);
    pclose(p);
    if (strcmp(function, "??") == 0) function[0] = '\0';
    if (!known_line(line)) line[0] = '\0';
}

const char *code_place(const char *elf, uint32_t pc, char *out, size_t size) {
    char function[128], line[256];
    addr2line("avr-addr2line", elf, pc, function, sizeof function, line, sizeof line);
    if (function[0] == '\0')
        snprintf(out, size, "PC 0x%04x", (unsigned)pc);
    else if (line[0] == '\0')
        snprintf(out, size, "%s (PC 0x%04x)", function, (unsigned)pc);
    else
        snprintf(out, size, "%s, %s (PC 0x%04x)", function, line, (unsigned)pc);
    return out;
}

const char *host_code_place(const char *so, uint64_t offset, char *out, size_t size, char *function,
                            size_t function_size) {
    char line[256];
    addr2line("addr2line", so, offset, function, function_size, line, sizeof line);
    if (function[0] == '\0')
        snprintf(out, size, "at offset 0x%llx of %s", (unsigned long long)offset, so);
    else if (line[0] == '\0')
        snprintf(out, size, "%s", function);
    else
        snprintf(out, size, "%s, %s", function, line);
    return out;
}

void fault_place_after_window(robot *r, const char *elf) {
    /* still in an interrupt (the tick that told, or another): next window */
    if (!r->console.overrun_pending || r->avr->interrupts.running_ptr != 0) return;
    r->console.overrun_pending = 0;
    char place[400];
    code_place(elf, r->avr->pc, place, sizeof place);
    fprintf(stderr, "openswarm-sim: %sthe handler past its limit: %s; a handler runs to completion "
                    "on the system thread, between threads: make it return, and do long work in a "
                    "thread of its own%s\n",
            r->console.prefix, place, strchr(place, ':') != NULL ? "" : " (its source line: openswarm run --debug)");
}
