// Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr.
// The simulator's firmware ELF check (sim/src/board/elf_check.c), any bytes:
// it refuses with a reason "<what> (<what to do>)", or accepts; and whatever
// it accepts, simavr 1.6's own reader (elf_read_firmware, what
// openswarm-sim calls next) reads without crashing, into an image that fits
// the ATmega328P's memories as avr_load_firmware then needs.
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <sim_elf.h>

#include "board/elf_check.h"
#include "fuzz_input_file.hpp"

static void quiet(avr_t *, const int, const char *, va_list) {}

static void fail(const char *what, const char *detail) {
    std::fprintf(stderr, "fuzz_elf_check: %s: %s\n", what, detail);
    std::abort();
}

static void check_reason(const char *why) {
    size_t n = std::strlen(why);
    if (n == 0 || why[n - 1] != ')' || std::strchr(why, '(') == nullptr)
        fail("a refusal without '<what> (<what to do>)'", why);
}

static void free_firmware(elf_firmware_t *fw) {
    std::free(fw->flash);
    std::free(fw->eeprom);
    std::free(fw->fuse);
    std::free(fw->lockbits);
    for (uint32_t i = 0; i < fw->symbolcount; i++) std::free(fw->symbol[i]);
    std::free(fw->symbol);
}

// What avr_load_firmware copies into the ATmega328P must fit it.
static void check_loadable(const elf_firmware_t *fw) {
    if ((uint64_t)fw->flashbase + fw->flashsize > ELF_CHECK_FLASH_BYTES) fail("accepted", "flash image past 32 KB");
    if (fw->eesize > ELF_CHECK_EEPROM_BYTES) fail("accepted", "EEPROM image past 1 KB");
    if (fw->fusesize > sizeof(((avr_t *)nullptr)->fuse)) fail("accepted", "more fuses than simavr keeps");
    if (std::memchr(fw->mmcu, '\0', sizeof fw->mmcu) == nullptr) fail("accepted", "MCU name unterminated");
    if (fw->mmcu[0] != '\0' && std::strcmp(fw->mmcu, "atmega328p") != 0) fail("accepted another MCU", fw->mmcu);
    if (fw->tracecount != 0) fail("accepted", "a VCD trace request");
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    char why[512];
    if (elf_check(data, size, why, sizeof why) != 0) {
        check_reason(why);
        return 0;
    }
    avr_global_logger_set(quiet);
    auto path = write_input("firmware.elf", data, size);
    elf_firmware_t fw;
    std::memset(&fw, 0, sizeof fw);
    if (elf_read_firmware(path.c_str(), &fw) != 0) fail("accepted", "simavr could not read it");
    check_loadable(&fw);
    free_firmware(&fw);
    return 0;
}
