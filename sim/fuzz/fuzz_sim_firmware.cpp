// Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: runs the simulator, which links libsimavr.
// Firmware that runs, any code: the input's bytes replace the start of the
// .text section of a known-good ELF (the disperse template; the rest of
// .text, the data and the symbols stay), so every input passes the ELF
// check and its instructions execute. Two robots in IR range run it for
// 20 ms of simulated time: whatever the code does (jumps anywhere, writes
// anywhere, sleeps with interrupts off, resets through the watchdog), the
// simulator ends with a status and tells any refusal, and never crashes or
// hangs. Whole-file mutations of ELFs are fuzz_elf_check's.
#include <cstring>
#include <elf.h>
#include <fstream>
#include <iterator>
#include <vector>

#include "fuzz_run_parts.hpp"

struct KnownGood {
    std::vector<uint8_t> bytes;
    size_t text_offset = 0, text_size = 0;
};

// The fixed firmware and where its .text lies in the file.
static const KnownGood &known_good() {
    static const KnownGood elf = [] {
        KnownGood k;
        std::ifstream in(FIXED_FIRMWARE, std::ios::binary);
        k.bytes.assign(std::istreambuf_iterator<char>(in), {});
        Elf32_Ehdr header;
        std::memcpy(&header, k.bytes.data(), sizeof header);
        auto section = [&](int i) {
            Elf32_Shdr s;
            std::memcpy(&s, k.bytes.data() + header.e_shoff + (size_t)i * header.e_shentsize, sizeof s);
            return s;
        };
        const char *names = (const char *)k.bytes.data() + section(header.e_shstrndx).sh_offset;
        for (int i = 0; i < header.e_shnum; i++)
            if (std::strcmp(names + section(i).sh_name, ".text") == 0) {
                k.text_offset = section(i).sh_offset;
                k.text_size = section(i).sh_size;
            }
        if (k.text_size == 0) std::abort(); // FIXED_FIRMWARE is ours: it has a .text
        return k;
    }();
    return elf;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    const KnownGood &elf = known_good();
    std::vector<uint8_t> patched = elf.bytes;
    std::memcpy(patched.data() + elf.text_offset, data, std::min(size, elf.text_size));
    auto path = write_input("firmware.elf", patched.data(), patched.size());
    SimulatorRun run = run_simulator({"--robots", "2", "--distance", "40", "--time", "0.02", "--quiet",
                                      path.string()});
    check_refusal_told(run);
    return 0;
}
