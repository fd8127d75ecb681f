/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later (see sim/COPYING). */
/* An Intel HEX image checked whole before libsimavr reads it (ihex_check.h).
 * A record is ':' then hex pairs: a data length, a 16-bit address, a type,
 * the data, a checksum that makes the bytes sum to 0. */
#include "board/ihex_check.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#define FLASH_BYTES 32768u
#define RECORD_OVERHEAD 5u /* length, address (2), type, checksum */
/* simavr 1.6 reads a line into 128 bytes and its record into 64; the
 * tools write 16 or 32 data bytes a record. */
#define MAX_DATA_BYTES 32u
#define MAX_LINE (1u + 2u * (RECORD_OVERHEAD + MAX_DATA_BYTES))
#define FROM_THE_BUILD "give the .hex the build wrote, or the .elf"

enum { DATA = 0, END_OF_FILE = 1, SEGMENT_BASE = 2, SEGMENT_START = 3, LINEAR_BASE = 4,
       LINEAR_START = 5 };

typedef struct hex_reader {
    char *why;
    size_t why_size;
    unsigned line;
    uint32_t base; /* from the last segment or linear base record */
    int ended;     /* its end-of-file record came */
    unsigned data_records;
} hex_reader;

static int refuse(hex_reader *r, const char *format, ...) {
    int n = snprintf(r->why, r->why_size, "line %u: ", r->line);
    va_list args;
    va_start(args, format);
    if (n >= 0 && (size_t)n < r->why_size) vsnprintf(r->why + n, r->why_size - (size_t)n, format, args);
    va_end(args);
    return -1;
}

static int hex_digit(uint8_t c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    return -1;
}

/* A line's record bytes, from its hex pairs, checked for length and sum. */
static int decode(hex_reader *r, const uint8_t *line, size_t length, uint8_t *record) {
    if (line[0] != ':')
        return r->line == 1 ? refuse(r, "not an Intel HEX file: its first line should start with "
                                        "':' (%s)", FROM_THE_BUILD)
                            : refuse(r, "does not start with ':' (%s)", FROM_THE_BUILD);
    if (length > MAX_LINE || length < 1u + 2u * RECORD_OVERHEAD || (length - 1u) % 2u != 0)
        return refuse(r, "%zu characters, not a record of up to %u data bytes (%s)", length,
                      MAX_DATA_BYTES, FROM_THE_BUILD);
    size_t n = (length - 1u) / 2u;
    uint8_t sum = 0;
    for (size_t i = 0; i < n; i++) {
        int high = hex_digit(line[1 + 2 * i]), low = hex_digit(line[2 + 2 * i]);
        if (high < 0 || low < 0)
            return refuse(r, "character %zu is not a hex digit (%s)", high < 0 ? 2 + 2 * i : 3 + 2 * i,
                          FROM_THE_BUILD);
        record[i] = (uint8_t)(high << 4 | low);
        sum = (uint8_t)(sum + record[i]);
    }
    if (n != RECORD_OVERHEAD + record[0])
        return refuse(r, "says %u data bytes but holds %zu (the file is damaged: %s)", record[0],
                      n - RECORD_OVERHEAD, FROM_THE_BUILD);
    if (sum != 0)
        return refuse(r, "bad checksum 0x%02X, expected 0x%02X (the file is damaged: %s)",
                      record[n - 1], (uint8_t)(record[n - 1] - sum), FROM_THE_BUILD);
    return 0;
}

static int take_record(hex_reader *r, const uint8_t *record) {
    uint8_t length = record[0], type = record[3];
    uint16_t address = (uint16_t)(record[1] << 8 | record[2]);
    static const uint8_t lengths[] = {[END_OF_FILE] = 0, [SEGMENT_BASE] = 2, [SEGMENT_START] = 4,
                                      [LINEAR_BASE] = 2, [LINEAR_START] = 4};
    if (type > LINEAR_START)
        return refuse(r, "record type %u, not one of Intel HEX's 0..5 (%s)", type, FROM_THE_BUILD);
    if (type != DATA && length != lengths[type])
        return refuse(r, "a record of type %u with %u data bytes, expected %u (%s)", type, length,
                      lengths[type], FROM_THE_BUILD);
    uint32_t value = (uint32_t)(record[4] << 8 | record[5]);
    switch (type) {
    case DATA:
        if ((uint64_t)r->base + address + length > FLASH_BYTES)
            return refuse(r, "data at 0x%llX, outside the ATmega328P's 32 KB flash (a .hex holds "
                             "the flash only: give a smaller program, or the .elf)",
                          (unsigned long long)r->base + address);
        r->data_records++;
        return 0;
    case END_OF_FILE: r->ended = 1; return 0;
    case SEGMENT_BASE: r->base = value << 4; return 0;
    case LINEAR_BASE: r->base = value << 16; return 0;
    default: return 0; /* a start address: the AVR starts at 0 */
    }
}

int ihex_check(const uint8_t *text, size_t size, char *why, size_t why_size) {
    hex_reader r = {.why = why, .why_size = why_size};
    if (why_size != 0) why[0] = '\0';
    for (size_t at = 0; at < size; at++) {
        const uint8_t *end = memchr(text + at, '\n', size - at);
        size_t length = (end != NULL ? (size_t)(end - text) : size) - at;
        const uint8_t *line = text + at;
        at += length;
        r.line++;
        if (length != 0 && line[length - 1] == '\r') length--;
        if (r.ended && length == 0) continue;
        if (r.ended) return refuse(&r, "comes after the end-of-file record (%s)", FROM_THE_BUILD);
        if (length == 0)
            return refuse(&r, "an empty line, where simavr would stop reading (%s)", FROM_THE_BUILD);
        uint8_t record[RECORD_OVERHEAD + MAX_DATA_BYTES];
        if (decode(&r, line, length, record) != 0 || take_record(&r, record) != 0) return -1;
    }
    r.line++;
    if (!r.ended)
        return refuse(&r, "the end, without the end-of-file record :00000001FF (the file is cut "
                          "short: %s)", FROM_THE_BUILD);
    if (r.data_records == 0)
        return refuse(&r, "the end, and no data record came (%s)", FROM_THE_BUILD);
    return 0;
}
