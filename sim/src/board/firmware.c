/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* Checking and loading a firmware ELF. */
#include <errno.h>
#include <stdarg.h>
#include <string.h>

#include <sim_elf.h>

#include "sim.h"

#define EM_AVR 83

/* Check the file before simavr sees it: simavr 1.6 crashes on some bad
 * input instead of reporting it. */
int firmware_check(const char *path) {
    FILE *f = fopen(path, "rb");
    if (f == NULL) {
        fprintf(stderr, "openswarm-sim: %s: %s\n", path, strerror(errno));
        return -1;
    }
    unsigned char h[20];
    size_t n = fread(h, 1, sizeof h, f);
    fclose(f);
    if (n < sizeof h || memcmp(h, "\177ELF", 4) != 0) {
        fprintf(stderr, "openswarm-sim: %s: not an ELF file (build the firmware first)\n", path);
        return -1;
    }
    if ((h[18] | h[19] << 8) != EM_AVR) {
        fprintf(stderr, "openswarm-sim: %s: an ELF for another CPU, not AVR "
                        "(build it with the Kilobot toolchain)\n", path);
        return -1;
    }
    return 0;
}

/* simavr reports what it loads at its lowest level; keep its errors only. */
static void log_errors_only(avr_t *avr, const int level, const char *format, va_list args) {
    (void)avr;
    if (level > LOG_ERROR || level == LOG_OUTPUT) return;
    vfprintf(stderr, format, args);
}

/* Sleeping costs no wall-clock time: simavr has already advanced the cycle
 * counter to the next timer event. */
static void fast_forward(avr_t *avr, avr_cycle_count_t how_long) {
    (void)avr;
    (void)how_long;
}

avr_t *firmware_load(const char *path) {
    avr_global_logger_set(log_errors_only);
    elf_firmware_t fw;
    memset(&fw, 0, sizeof fw);
    if (elf_read_firmware(path, &fw) != 0) {
        fprintf(stderr, "openswarm-sim: %s: cannot read the firmware\n", path);
        return NULL;
    }
    if (fw.mmcu[0] == '\0' || fw.frequency == 0) {
        fprintf(stderr, "openswarm-sim: %s: no MCU record in the ELF; link it with the OpenSwarm "
                        "port (it adds ports/kilobot/src/mcu_tag.c)\n", path);
        return NULL;
    }
    avr_t *avr = avr_make_mcu_by_name(fw.mmcu);
    if (avr == NULL) {
        fprintf(stderr, "openswarm-sim: %s: simavr does not know the MCU '%s'\n", path, fw.mmcu);
        return NULL;
    }
    avr_init(avr);
    avr->log = LOG_ERROR;
    avr_load_firmware(avr, &fw);
    avr->sleep = fast_forward;
    return avr;
}
