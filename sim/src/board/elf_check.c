/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later (see sim/COPYING). */
/* A firmware ELF checked whole before libsimavr reads it (elf_check.h).
 *
 * What simavr 1.6's elf_read_firmware does, and so what must hold first:
 * it walks every section after the first and asks libelf for its name in
 * the e_shstrndx table (strcmp on a NULL name crashes); takes .text and
 * .data as the flash image, placed at the value of a symbol __vectors
 * (avr_loadcode aborts if it passes the flash's end), .eeprom, .fuse
 * (copied into 6 bytes), .lock (read from .fuse's data: a crash without
 * one) and .bss by name, whatever their type (a NOBITS .text has no bytes
 * to copy); divides a symbol table's size by its entry size and asks libelf
 * for each entry's name; and parses the .mmcu records with strcpy into
 * fixed fields. */
#include "board/elf_check.h"

#include <elf.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#define EHDR_BYTES 52u
#define PHDR_BYTES 32u
#define SHDR_BYTES 40u
#define SYM_BYTES 16u
#define AVR5_CORE 5u /* e_flags' core of the ATmega328P (avr-gcc's avr5) */
#define CORE_MASK 0x7fu
/* simavr sorts the symbols by insertion, in quadratic time: a firmware
 * that fits 32 KB of flash has far fewer. */
#define MAX_SYMBOLS 16384u
#define MMCU_NAME_BYTES 64u /* simavr's elf_firmware_t.mmcu */
#define KILOBOT_MCU "atmega328p"
#define MIN_CLOCK_HZ 1000000u
#define MAX_CLOCK_HZ 20000000u
#define FUSE_BYTES 3u /* low, high, extended (simavr keeps 6) */
#define BUILD_AGAIN "the file is damaged or cut short: build the firmware again"

/* .mmcu record tags (simavr's avr_mcu_section.h). */
enum { MMCU_NAME = 1, MMCU_FREQUENCY = 2, MMCU_VCC = 3, MMCU_AVCC = 4, MMCU_AREF = 5,
       MMCU_COMMAND = 10, MMCU_CONSOLE = 11, MMCU_VCD_FIRST = 12, MMCU_VCD_LAST = 16,
       MMCU_EXTERNAL_PULL = 17 };

typedef struct elf_view {
    const uint8_t *bytes;
    size_t size;
    uint32_t flags, phoff, shoff;
    uint16_t phnum, shnum, shstrndx;
    uint32_t flashbase; /* __vectors, where simavr loads the flash image */
    char *why;
    size_t why_size;
} elf_view;

typedef struct section {
    uint32_t name, type, flags, addr, offset, size, link, entsize;
} section;

/* A region of the ATmega328P as the ELF addresses it: what lies in
 * [space_start, space_end) must fit [start, end). Addresses above the
 * last (the .mmcu record at 0x910000) are not loaded. */
typedef struct region {
    uint32_t space_start, space_end, start, end;
    const char *name;
} region;

static const region regions[] = {
    {0x000000u, 0x800000u, 0, ELF_CHECK_FLASH_BYTES, "32 KB flash"},
    {0x800000u, 0x810000u, ELF_CHECK_SRAM_START, ELF_CHECK_SRAM_END, "2 KB SRAM (0x800100..0x8008FF)"},
    {0x810000u, 0x820000u, 0x810000u, 0x810000u + ELF_CHECK_EEPROM_BYTES, "1 KB EEPROM"},
    {0x820000u, 0x830000u, 0x820000u, 0x820000u + FUSE_BYTES, "3 fuse bytes"},
    {0x830000u, 0x840000u, 0x830000u, 0x830001u, "1 lock byte"},
    {0x840000u, 0x850000u, 0x840000u, 0x840003u, "3 signature bytes"},
};

static int refuse(elf_view *v, const char *format, ...) {
    va_list args;
    va_start(args, format);
    vsnprintf(v->why, v->why_size, format, args);
    va_end(args);
    return -1;
}

static uint16_t rd16(const elf_view *v, uint64_t at) {
    return (uint16_t)(v->bytes[at] | v->bytes[at + 1] << 8);
}

static uint32_t rd32(const elf_view *v, uint64_t at) {
    return (uint32_t)v->bytes[at] | (uint32_t)v->bytes[at + 1] << 8 |
           (uint32_t)v->bytes[at + 2] << 16 | (uint32_t)v->bytes[at + 3] << 24;
}

static int in_file(const elf_view *v, uint64_t offset, uint64_t length) {
    return offset <= v->size && length <= v->size - offset;
}

static section section_at(const elf_view *v, uint16_t index) {
    uint64_t at = v->shoff + (uint64_t)index * SHDR_BYTES;
    section s = {rd32(v, at), rd32(v, at + 4), rd32(v, at + 8), rd32(v, at + 12),
                 rd32(v, at + 16), rd32(v, at + 20), rd32(v, at + 24), rd32(v, at + 36)};
    return s;
}

/* libelf reads from the file any section but a NOBITS one (even a
 * NULL-typed one, if asked for its data). */
static int occupies_file(const section *s) {
    return s->type != SHT_NOBITS;
}

/* The string at offset in a string table checked by check_string_table,
 * or NULL where libelf would give none: past its end, or unterminated. */
static const char *string_in(const elf_view *v, const section *table, uint32_t offset) {
    if (offset >= table->size) return NULL;
    const char *s = (const char *)v->bytes + table->offset + offset;
    return memchr(s, '\0', table->size - offset) != NULL ? s : NULL;
}

static const char *name_of(const elf_view *v, const section *s) {
    section names = section_at(v, v->shstrndx);
    return string_in(v, &names, s->name);
}

/* The identifiers an image carries are printed in messages only if they
 * are plain text. */
static const char *printable(const char *name) {
    for (const char *c = name; *c != '\0'; c++)
        if (*c < ' ' || *c > '~') return "<unprintable name>";
    return name;
}

static int check_ident(elf_view *v) {
    if (v->size < SELFMAG || memcmp(v->bytes, ELFMAG, SELFMAG) != 0)
        return refuse(v, "not an ELF file (build the firmware first, and give its .elf or .hex)");
    if (v->size < EHDR_BYTES)
        return refuse(v, "%zu bytes, too short for an ELF file's %u-byte header (%s)", v->size,
                      EHDR_BYTES, BUILD_AGAIN);
    if (rd16(v, 18) != EM_AVR)
        return refuse(v, "an ELF for another CPU, not AVR (machine %u) (build it with the Kilobot "
                         "toolchain: avr-gcc -mmcu=atmega328p)", rd16(v, 18));
    if (v->bytes[EI_CLASS] != ELFCLASS32 || v->bytes[EI_DATA] != ELFDATA2LSB)
        return refuse(v, "not a 32-bit little-endian ELF, as every AVR ELF is (%s)", BUILD_AGAIN);
    if (v->bytes[EI_VERSION] != EV_CURRENT || rd32(v, 20) != EV_CURRENT)
        return refuse(v, "ELF version %u/%u, expected 1 (%s)", v->bytes[EI_VERSION], rd32(v, 20),
                      BUILD_AGAIN);
    if (rd16(v, 16) != ET_EXEC)
        return refuse(v, "not a linked executable (ELF type %u): an object file or library has no "
                         "program to run (link it: build the app with openswarm build)", rd16(v, 16));
    return 0;
}

static int check_tables(elf_view *v) {
    v->flags = rd32(v, 36);
    v->phoff = rd32(v, 28);
    v->shoff = rd32(v, 32);
    v->phnum = rd16(v, 44);
    v->shnum = rd16(v, 48);
    v->shstrndx = rd16(v, 50);
    if (rd16(v, 40) != EHDR_BYTES || (v->phnum != 0 && rd16(v, 42) != PHDR_BYTES) ||
        (v->shnum != 0 && rd16(v, 46) != SHDR_BYTES))
        return refuse(v, "header sizes %u/%u/%u, expected 52/32/40 for a 32-bit ELF (%s)",
                      rd16(v, 40), rd16(v, 42), rd16(v, 46), BUILD_AGAIN);
    /* 0xffff would send libelf to section 0 for the real count */
    if (v->phnum == PN_XNUM || !in_file(v, v->phoff, (uint64_t)v->phnum * PHDR_BYTES))
        return refuse(v, "its program header table (%u entries at offset %u) runs past the end of "
                         "the file (%zu bytes) (%s)", v->phnum, v->phoff, v->size, BUILD_AGAIN);
    if (v->shnum == 0)
        return refuse(v, "no section table: simavr finds the program by its sections (link it "
                         "with avr-gcc, and do not strip the section headers)");
    if (v->shnum >= SHN_LORESERVE || !in_file(v, v->shoff, (uint64_t)v->shnum * SHDR_BYTES))
        return refuse(v, "its section table (%u entries at offset %u) runs past the end of the "
                         "file (%zu bytes) (%s)", v->shnum, v->shoff, v->size, BUILD_AGAIN);
    return 0;
}

/* A table libelf will read strings from: a string table, in the file,
 * not compressed. */
static int check_string_table(elf_view *v, uint32_t index, const char *of) {
    if (index == 0 || index >= v->shnum)
        return refuse(v, "%s names section %u as its string table; there are %u sections (%s)", of,
                      index, v->shnum, BUILD_AGAIN);
    section s = section_at(v, (uint16_t)index);
    if (s.type != SHT_STRTAB || (s.flags & SHF_COMPRESSED) != 0)
        return refuse(v, "%s names section %u as its string table, which is not a plain one "
                         "(type %u) (%s)", of, index, s.type, BUILD_AGAIN);
    return 0;
}

static int check_segments(elf_view *v) {
    for (uint16_t i = 0; i < v->phnum; i++) {
        uint64_t at = v->phoff + (uint64_t)i * PHDR_BYTES;
        uint32_t offset = rd32(v, at + 4), filesz = rd32(v, at + 16), memsz = rd32(v, at + 20);
        if (!in_file(v, offset, filesz))
            return refuse(v, "segment %u (%u bytes at offset %u) runs past the end of the file "
                             "(%zu bytes) (%s)", i, filesz, offset, v->size, BUILD_AGAIN);
        if (rd32(v, at) == PT_LOAD && filesz > memsz)
            return refuse(v, "segment %u holds %u bytes of contents in %u bytes of memory (%s)", i,
                          filesz, memsz, BUILD_AGAIN);
    }
    return 0;
}

/* Every section after the first: its contents in the file, its name in
 * the section name table (simavr compares every one). */
static int check_sections(elf_view *v) {
    if (check_string_table(v, v->shstrndx, "the ELF header") != 0) return -1;
    section names = section_at(v, v->shstrndx);
    if (!in_file(v, names.offset, names.size))
        return refuse(v, "its section name table runs past the end of the file (%s)", BUILD_AGAIN);
    for (uint16_t i = 1; i < v->shnum; i++) {
        section s = section_at(v, i);
        if (occupies_file(&s) && !in_file(v, s.offset, s.size))
            return refuse(v, "section %u (%u bytes at offset %u) runs past the end of the file "
                             "(%zu bytes) (%s)", i, s.size, s.offset, v->size, BUILD_AGAIN);
        if (name_of(v, &s) == NULL)
            return refuse(v, "section %u's name (at %u) is not in the section name table (%s)", i,
                          s.name, BUILD_AGAIN);
    }
    return 0;
}

/* The sections simavr takes by name: at most one of each; those it copies
 * bytes from must have plain bytes (.bss is only measured, but libelf
 * would convert a .bss of another type, and may fail). */
static const char *const named[] = {".text", ".data", ".eeprom", ".fuse", ".lock", ".mmcu", ".bss"};
#define N_NAMED (sizeof named / sizeof named[0])

/* Index of the section called name, 0 if none. */
static uint16_t find_section(const elf_view *v, const char *name) {
    for (uint16_t i = 1; i < v->shnum; i++) {
        section s = section_at(v, i);
        if (strcmp(name_of(v, &s), name) == 0) return i;
    }
    return 0;
}

static int check_named_sections(elf_view *v) {
    for (size_t k = 0; k < N_NAMED; k++) {
        uint16_t first = find_section(v, named[k]);
        for (uint16_t i = (uint16_t)(first + 1u); first != 0 && i < v->shnum; i++) {
            section s = section_at(v, i);
            if (strcmp(name_of(v, &s), named[k]) == 0)
                return refuse(v, "two %s sections (%u and %u) (%s)", named[k], first, i, BUILD_AGAIN);
        }
        section s = section_at(v, first);
        int measured_only = strcmp(named[k], ".bss") == 0 && s.type == SHT_NOBITS;
        if (first != 0 && s.size != 0 && !measured_only &&
            (s.type != SHT_PROGBITS || (s.flags & SHF_COMPRESSED) != 0))
            return refuse(v, "section %s (type %u) holds no plain contents to load (%s)", named[k],
                          s.type, BUILD_AGAIN);
    }
    if (find_section(v, ".lock") != 0 && find_section(v, ".fuse") == 0)
        return refuse(v, "a .lock section without a .fuse section: simavr 1.6 reads the lock byte "
                         "from .fuse and crashes (set the fuses too, with FUSES, or drop LOCKBITS)");
    return 0;
}

static int check_mmcu_address(elf_view *v, uint8_t tag, const uint8_t *body) {
    uint16_t address = (uint16_t)(body[0] | body[1] << 8);
    if (address == 0 || (address >= 0x20 && address <= 0xff)) return 0;
    return refuse(v, "its .mmcu %s register is at 0x%x, outside the ATmega328P's I/O registers "
                     "(0x20..0xFF) (give AVR_MCU_SIMAVR_%s an I/O register, e.g. GPIOR1)",
                  tag == MMCU_COMMAND ? "command" : "console", address,
                  tag == MMCU_COMMAND ? "COMMAND" : "CONSOLE");
}

/* One .mmcu record's body: long enough for what simavr reads from it. */
static int check_mmcu_record(elf_view *v, uint8_t tag, const uint8_t *body, uint8_t length,
                             const char **mcu) {
    switch (tag) {
    case MMCU_NAME:
        if (memchr(body, '\0', length < MMCU_NAME_BYTES ? length : MMCU_NAME_BYTES) == NULL)
            return refuse(v, "its .mmcu MCU name is not a string of fewer than %u characters (%s)",
                          MMCU_NAME_BYTES, BUILD_AGAIN);
        *mcu = (const char *)body;
        return 0;
    case MMCU_FREQUENCY: {
        if (length < 4) break;
        uint32_t hz = (uint32_t)body[0] | (uint32_t)body[1] << 8 | (uint32_t)body[2] << 16 |
                      (uint32_t)body[3] << 24;
        if (hz != 0 && (hz < MIN_CLOCK_HZ || hz > MAX_CLOCK_HZ))
            return refuse(v, "its .mmcu clock, %u Hz, is outside the ATmega328P's 1..20 MHz "
                             "(the Kilobot runs at 8 MHz: build with F_CPU=8000000)", hz);
        return 0;
    }
    case MMCU_VCC: case MMCU_AVCC: case MMCU_AREF: case MMCU_EXTERNAL_PULL:
        return length < 4 ? refuse(v, "its .mmcu record %u is %u bytes long, expected 4 (%s)", tag,
                                   length, BUILD_AGAIN) : 0;
    case MMCU_COMMAND: case MMCU_CONSOLE:
        if (length < 2) break;
        return check_mmcu_address(v, tag, body);
    default:
        if (tag >= MMCU_VCD_FIRST && tag <= MMCU_VCD_LAST)
            return refuse(v, "its .mmcu record asks simavr for a VCD trace (AVR_MCU_VCD_*), which "
                             "openswarm-sim does not take from the firmware (remove it; "
                             "openswarm-sim --vcd FILE records the LED pins and the motors)");
        return 0; /* simavr skips the others */
    }
    return refuse(v, "its .mmcu record %u is %u bytes long, too short for its value (%s)", tag,
                  length, BUILD_AGAIN);
}

/* The .mmcu records (tag, length, body), tiling the section; the MCU
 * name, if one is given. */
static int check_mmcu(elf_view *v, const char **mcu) {
    *mcu = NULL;
    uint16_t index = find_section(v, ".mmcu");
    if (index == 0) return 0;
    section s = section_at(v, index);
    const uint8_t *at = v->bytes + s.offset;
    for (uint32_t left = s.size; left != 0;) {
        if (left < 2u || at[1] > left - 2u)
            return refuse(v, "its .mmcu record %u at byte %u runs past the section's end (%s)", at[0],
                          s.size - left, BUILD_AGAIN);
        if (check_mmcu_record(v, at[0], at + 2, at[1], mcu) != 0) return -1;
        left -= 2u + at[1];
        at += 2u + at[1];
    }
    return 0;
}

/* The MCU avr-gcc wrote in .note.gnu.avr.deviceinfo, or NULL if none is
 * readable (simavr ignores the note: only a clear name counts). The note:
 * namesz 4, descsz, type, "AVR\0", then the description: flash, SRAM and
 * EEPROM start and size (six words), a table of string offsets (its
 * length in bytes, itself included, then the offsets; the first names the
 * device) and the strings. */
static const char *device_in_note(const elf_view *v) {
    uint16_t index = find_section(v, ".note.gnu.avr.deviceinfo");
    section s = section_at(v, index);
    if (index == 0 || s.type != SHT_NOTE || s.size < 16u) return NULL;
    uint32_t namesz = rd32(v, s.offset), descsz = rd32(v, s.offset + 4);
    if (namesz != 4u || memcmp(v->bytes + s.offset + 12, "AVR", 4) != 0 || descsz > s.size - 16u ||
        descsz < 32u)
        return NULL;
    uint64_t desc = (uint64_t)s.offset + 16;
    uint32_t table = rd32(v, desc + 24), name = rd32(v, desc + 28);
    if (table < 8u || table > descsz - 24u || name >= descsz - 24u - table) return NULL;
    const char *strings = (const char *)v->bytes + desc + 24 + table;
    return memchr(strings + name, '\0', descsz - 24u - table - name) != NULL ? strings + name : NULL;
}

/* Built for the Kilobot's ATmega328P: by the .mmcu record's name, else by
 * avr-gcc's device note, and by the core in e_flags. */
static int check_device(elf_view *v, const char *mcu) {
    const char *device = mcu != NULL && mcu[0] != '\0' ? mcu : device_in_note(v);
    if (device != NULL && strcmp(device, KILOBOT_MCU) != 0)
        return refuse(v, "built for the %s, but the Kilobot is an ATmega328P (build with "
                         "-mmcu=atmega328p)", printable(device));
    uint32_t core = v->flags & CORE_MASK;
    if (core != 0 && core != AVR5_CORE)
        return refuse(v, "built for the avr%u core, but the Kilobot's ATmega328P is avr5 (build "
                         "with -mmcu=atmega328p)", core);
    return 0;
}

static int check_symbol(elf_view *v, const section *strings, uint64_t at, uint32_t i) {
    const char *name = string_in(v, strings, rd32(v, at));
    if (name == NULL)
        return refuse(v, "symbol %u's name (at %u) is not in its string table (%s)", i,
                      rd32(v, at), BUILD_AGAIN);
    uint16_t shndx = rd16(v, at + 14);
    if (shndx >= v->shnum && shndx != SHN_ABS && shndx != SHN_COMMON)
        return refuse(v, "symbol %s lies in section %u; there are %u (%s)", printable(name), shndx,
                      v->shnum, BUILD_AGAIN);
    uint8_t info = v->bytes[at + 12];
    if ((ELF32_ST_BIND(info) == STB_GLOBAL || ELF32_ST_TYPE(info) == STT_FUNC ||
         ELF32_ST_TYPE(info) == STT_OBJECT) && strcmp(name, "__vectors") == 0)
        v->flashbase = rd32(v, at + 4); /* simavr's flash image starts there */
    return 0;
}

static int check_symbol_table(elf_view *v, uint16_t index) {
    section s = section_at(v, index);
    if (s.entsize != SYM_BYTES || s.size % SYM_BYTES != 0 || (s.flags & SHF_COMPRESSED) != 0)
        return refuse(v, "symbol table %u has %u-byte entries in %u bytes, expected 16-byte "
                         "ones (%s)", index, s.entsize, s.size, BUILD_AGAIN);
    if (s.size / SYM_BYTES > MAX_SYMBOLS)
        return refuse(v, "symbol table %u holds %u symbols, more than a 32 KB firmware has (%s)",
                      index, s.size / SYM_BYTES, BUILD_AGAIN);
    char of[32];
    snprintf(of, sizeof of, "symbol table %u", index);
    if (check_string_table(v, s.link, of) != 0) return -1;
    section strings = section_at(v, (uint16_t)s.link);
    for (uint32_t i = 0; i < s.size / SYM_BYTES; i++)
        if (check_symbol(v, &strings, (uint64_t)s.offset + (uint64_t)i * SYM_BYTES, i) != 0)
            return -1;
    return 0;
}

static int check_symbols(elf_view *v) {
    v->flashbase = 0;
    for (uint16_t i = 1; i < v->shnum; i++)
        if (section_at(v, i).type == SHT_SYMTAB && check_symbol_table(v, i) != 0) return -1;
    return 0;
}

/* What is loaded at address lies within its memory. */
static int check_fit(elf_view *v, const char *what, uint32_t address, uint32_t bytes) {
    if (bytes == 0) return 0;
    for (size_t k = 0; k < sizeof regions / sizeof regions[0]; k++) {
        const region *r = &regions[k];
        if (address < r->space_start || address >= r->space_end) continue;
        if (address >= r->start && (uint64_t)address + bytes <= r->end) return 0;
        return refuse(v, "%s (%u bytes at 0x%x) does not fit the ATmega328P's %s (make it "
                         "smaller; the Kilobot's MCU has no more)", what, bytes, address, r->name);
    }
    return 0;
}

static int check_loaded_sections(elf_view *v) {
    for (uint16_t i = 1; i < v->shnum; i++) {
        section s = section_at(v, i);
        char what[80];
        snprintf(what, sizeof what, "section %s", printable(name_of(v, &s)));
        if ((s.flags & SHF_ALLOC) != 0 && check_fit(v, what, s.addr, s.size) != 0) return -1;
    }
    return 0;
}

static int check_loaded_segments(elf_view *v) {
    for (uint16_t i = 0; i < v->phnum; i++) {
        uint64_t at = v->phoff + (uint64_t)i * PHDR_BYTES;
        if (rd32(v, at) != PT_LOAD) continue;
        char what[32];
        snprintf(what, sizeof what, "segment %u", i);
        /* where it runs, and where its initial contents are kept (.data's in flash) */
        if (check_fit(v, what, rd32(v, at + 8), rd32(v, at + 20)) != 0 ||
            check_fit(v, what, rd32(v, at + 12), rd32(v, at + 16)) != 0)
            return -1;
    }
    return 0;
}

static uint32_t size_of(const elf_view *v, const char *name) {
    uint16_t index = find_section(v, name);
    return index != 0 ? section_at(v, index).size : 0;
}

/* The image simavr builds: .text then .data's initial values, at
 * __vectors; the EEPROM and fuses it copies, whatever their addresses. */
static int check_flash_image(elf_view *v) {
    uint64_t bytes = (uint64_t)size_of(v, ".text") + size_of(v, ".data");
    if ((uint64_t)v->flashbase + bytes > ELF_CHECK_FLASH_BYTES)
        return refuse(v, "its program (.text and .data, %llu bytes from 0x%x) does not fit the "
                         "ATmega328P's 32 KB flash (make it smaller)",
                      (unsigned long long)bytes, v->flashbase);
    if (size_of(v, ".eeprom") > ELF_CHECK_EEPROM_BYTES)
        return refuse(v, "its .eeprom (%u bytes) does not fit the ATmega328P's 1 KB EEPROM (make "
                         "it smaller)", size_of(v, ".eeprom"));
    if (size_of(v, ".fuse") > FUSE_BYTES)
        return refuse(v, "its .fuse holds %u bytes; the ATmega328P has 3 fuse bytes (%s)",
                      size_of(v, ".fuse"), BUILD_AGAIN);
    return 0;
}

int elf_check(const uint8_t *image, size_t size, char *why, size_t why_size) {
    elf_view v = {.bytes = image, .size = size, .why = why, .why_size = why_size};
    if (why_size != 0) why[0] = '\0';
    const char *mcu = NULL;
    if (check_ident(&v) != 0 || check_tables(&v) != 0 || check_segments(&v) != 0 ||
        check_sections(&v) != 0 || check_named_sections(&v) != 0 || check_mmcu(&v, &mcu) != 0 ||
        check_device(&v, mcu) != 0 || check_symbols(&v) != 0 || check_loaded_sections(&v) != 0 ||
        check_loaded_segments(&v) != 0 || check_flash_image(&v) != 0)
        return -1;
    return 0;
}
