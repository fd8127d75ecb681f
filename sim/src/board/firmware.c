/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* Checking and loading a firmware ELF. */
#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include <sim_elf.h>
#include <sim_hex.h>

#include "sim.h"
#include "board/elf_check.h"
#include "board/ihex_check.h"
#include "board/invalid_opcode.h"

#define KILOBOT_FLASH_BYTES 32768
/* A firmware ELF with its debugging sections is well under this. */
#define MAX_FIRMWARE_FILE_BYTES (64u << 20)

/* A prebuilt Intel HEX image (what KiloGUI uploads): a text file of
 * ':'-records. */
static int is_intel_hex(const char *path) {
    size_t n = strlen(path);
    return n > 4 && strcmp(path + n - 4, ".hex") == 0;
}

/* The whole file, or NULL (said why) if it cannot be read. */
static uint8_t *read_whole(const char *path, size_t *size) {
    FILE *f = fopen(path, "rb");
    struct stat st;
    if (f == NULL || fstat(fileno(f), &st) != 0) {
        fprintf(stderr, "openswarm-sim: %s: %s\n", path, strerror(errno));
        if (f != NULL) fclose(f);
        return NULL;
    }
    if (st.st_size > (off_t)MAX_FIRMWARE_FILE_BYTES) {
        fprintf(stderr, "openswarm-sim: %s: larger than %u MB, which no firmware is (give the .elf "
                        "or .hex the build wrote)\n", path, MAX_FIRMWARE_FILE_BYTES >> 20);
        fclose(f);
        return NULL;
    }
    uint8_t *bytes = malloc((size_t)st.st_size + 1u);
    *size = bytes != NULL ? fread(bytes, 1, (size_t)st.st_size, f) : 0;
    if (bytes == NULL || ferror(f)) {
        fprintf(stderr, "openswarm-sim: %s: %s\n", path, strerror(errno));
        free(bytes);
        bytes = NULL;
    }
    fclose(f);
    return bytes;
}

/* Check the whole file before simavr sees it: simavr 1.6 crashes on bad
 * input instead of reporting it (board/elf_check.c says how). */
int firmware_check(const char *path) {
    size_t size;
    uint8_t *bytes = read_whole(path, &size);
    if (bytes == NULL) return -1;
    char why[512];
    int status = is_intel_hex(path) ? ihex_check(bytes, size, why, sizeof why)
                                    : elf_check(bytes, size, why, sizeof why);
    free(bytes);
    if (status != 0) fprintf(stderr, "openswarm-sim: %s: %s\n", path, why);
    return status;
}

/* simavr reports what it loads at its lowest level; keep its errors only.
 * An invalid opcode is a crash: simavr 1.6 logs it and steps over it, so
 * code run from a wild jump printed a line per instruction for as long as
 * the run lasted (100000 lines in 20 ms of simulated time, found by
 * fuzz_sim_firmware) instead of stopping. Its line is left out: the run's
 * report names the opcode and where it is in the sources. It is logged
 * while the PC still points at the opcode. */
static void log_errors_only(avr_t *avr, const int level, const char *format, va_list args) {
    if (level > LOG_ERROR || level == LOG_OUTPUT) return;
    if (avr != NULL && strstr(format, "Invalid Opcode") != NULL) {
        invalid_opcode_stop(avr, avr->pc);
        return;
    }
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
    fw->frequency = KILOBOT_CLOCK_HZ;
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
    if (board_widen_memories(avr) != 0) {
        fprintf(stderr, "openswarm-sim: %s: out of memory for the MCU's memories\n", path);
        return NULL;
    }
    avr->log = LOG_ERROR;
    avr_load_firmware(avr, &fw);
    if (hex) free(fw.flash);
    avr->sleep = fast_forward;
    return avr;
}
