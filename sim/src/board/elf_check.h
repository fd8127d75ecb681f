/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later (see sim/COPYING). */
/* A firmware ELF checked whole before libsimavr reads it.
 *
 * simavr 1.6's reader (sim_elf.c, through libelf) trusts its input: a
 * section name or symbol name libelf cannot give back, a symbol table with
 * no entry size, a .lock without a .fuse, an image larger than the flash or
 * an .mmcu record longer than its field each crash it or abort. This check
 * refuses all of them first, and an ELF built for another MCU, with the
 * reason and the fix. Plain C on a byte buffer, no libelf and no libsimavr,
 * so that it can be fuzzed alone (tests/fuzz/fuzz_elf_check.c). */
#ifndef OPENSWARM_SIM_ELF_CHECK_H
#define OPENSWARM_SIM_ELF_CHECK_H

#include <stddef.h>
#include <stdint.h>

/* The ATmega328P's memories, as the ELF's address spaces lay them out
 * (avr-libc's linker scripts put data at 0x800000, EEPROM at 0x810000). */
#define ELF_CHECK_FLASH_BYTES 32768u
#define ELF_CHECK_SRAM_START 0x800100u
#define ELF_CHECK_SRAM_END 0x800900u /* one past the last byte, 0x8008FF */
#define ELF_CHECK_EEPROM_BYTES 1024u

#ifdef __cplusplus
extern "C" {
#endif

/* 0 if simavr may read the image; -1 if not, with why (always
 * NUL-terminated, cut to why_size) saying what is wrong and, in
 * parentheses, what to do: "<what is wrong> (<what to do>)". */
int elf_check(const uint8_t *image, size_t size, char *why, size_t why_size);

#ifdef __cplusplus
}
#endif

#endif
