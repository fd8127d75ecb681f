/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* Checking and loading a firmware ELF. */
#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include <sim_elf.h>
#include <sim_hex.h>

#include "sim.h"

#define EM_AVR 83
#define KILOBOT_FLASH_BYTES 32768

/* A prebuilt Intel HEX image (what KiloGUI uploads): a text file of
 * ':'-records. */
static int is_intel_hex(const char *path) {
    size_t n = strlen(path);
    return n > 4 && strcmp(path + n - 4, ".hex") == 0;
}

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
    if (is_intel_hex(path)) {
        if (n > 0 && h[0] == ':') return 0;
        fprintf(stderr, "openswarm-sim: %s: not an Intel HEX file (its first line should start "
                        "with ':'); give the .hex the build wrote, or the .elf\n", path);
        return -1;
    }
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

/* A .hex holds flash only: its chunks laid out from address 0. */
static int read_hex(const char *path, elf_firmware_t *fw) {
    ihex_chunk_p chunks = NULL;
    int n = read_ihex_chunks(path, &chunks);
    if (n <= 0) return -1;
    uint32_t end = 0;
    for (int i = 0; i < n; i++)
        if (chunks[i].baseaddr + chunks[i].size > end) end = chunks[i].baseaddr + chunks[i].size;
    fw->flash = end <= KILOBOT_FLASH_BYTES ? calloc(1, end) : NULL;
    if (fw->flash != NULL) {
        for (int i = 0; i < n; i++)
            memcpy(fw->flash + chunks[i].baseaddr, chunks[i].data, chunks[i].size);
        fw->flashsize = end;
    }
    free_ihex_chunks(chunks);
    return fw->flash != NULL ? 0 : -1;
}

/* Firmware built without OpenSwarm's port carries no MCU record (a
 * classic kilolib Makefile's ELF, any .hex): it is a Kilobot's. */
static void assume_kilobot(const char *path, elf_firmware_t *fw) {
    if (fw->mmcu[0] != '\0' && fw->frequency != 0) return;
    strcpy(fw->mmcu, "atmega328p");
    fw->frequency = 8000000;
    static int said;
    if (!said++)
        fprintf(stderr, "openswarm-sim: %s has no MCU record: running it as a Kilobot's "
                        "ATmega328P at 8 MHz\n", path);
}

avr_t *firmware_load(const char *path) {
    avr_global_logger_set(log_errors_only);
    elf_firmware_t fw;
    memset(&fw, 0, sizeof fw);
    int hex = is_intel_hex(path);
    if ((hex ? read_hex(path, &fw) : elf_read_firmware(path, &fw)) != 0) {
        fprintf(stderr, "openswarm-sim: %s: cannot read the firmware%s\n", path,
                hex ? " (a bad record, or an image larger than the ATmega328P's 32 KB flash)" : "");
        return NULL;
    }
    assume_kilobot(path, &fw);
    avr_t *avr = avr_make_mcu_by_name(fw.mmcu);
    if (avr == NULL) {
        fprintf(stderr, "openswarm-sim: %s: simavr does not know the MCU '%s'\n", path, fw.mmcu);
        return NULL;
    }
    avr_init(avr);
    avr->log = LOG_ERROR;
    avr_load_firmware(avr, &fw);
    if (hex) free(fw.flash);
    avr->sleep = fast_forward;
    return avr;
}
