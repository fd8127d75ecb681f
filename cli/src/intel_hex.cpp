#include "intel_hex.hpp"

#include <fstream>
#include <string>

#include "regular_file.hpp"

namespace openswarm {

namespace {

const char *const REBUILD = "; rebuild it (openswarm build) or give the .hex avr-objcopy -O ihex wrote";

// A HEX line's bytes after the colon; throws on a character not hex.
std::vector<uint8_t> record_bytes(const std::string &where, const std::string &line) {
    std::vector<uint8_t> bytes;
    if (line.size() < 11 || line[0] != ':' || (line.size() - 1) % 2 != 0)
        throw HexError(where + ": not an Intel HEX record (':' and an even number of hex digits)" + REBUILD);
    for (size_t i = 1; i + 1 < line.size(); i += 2) {
        try {
            size_t used = 0;
            int value = std::stoi(line.substr(i, 2), &used, 16);
            if (used != 2) throw std::invalid_argument("digit");
            bytes.push_back((uint8_t)value);
        } catch (const std::exception &) {
            throw HexError(where + ": '" + line.substr(i, 2) + "' is not a hex byte" + REBUILD);
        }
    }
    return bytes;
}

}  // namespace

std::vector<uint8_t> read_intel_hex(const std::filesystem::path &file) {
    std::string what = not_a_regular_file(file);
    if (!what.empty()) throw HexError(file.string() + " is " + what + "; give the app's .hex file");
    std::ifstream in(file);
    if (!in) throw HexError(file.string() + ": cannot read it; check the path (openswarm build makes it)");
    std::vector<uint8_t> flash;
    uint32_t base = 0; // from extended segment (02) and linear (04) records
    std::string line;
    for (int number = 1; std::getline(in, line); number++) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty()) continue;
        std::string where = file.string() + ":" + std::to_string(number);
        std::vector<uint8_t> b = record_bytes(where, line);
        if (b.size() != 5u + b[0]) throw HexError(where + ": the record's length byte says " +
                                                  std::to_string(b[0]) + " data bytes, it has " +
                                                  std::to_string(b.size() - 5) + REBUILD);
        uint8_t sum = 0;
        for (uint8_t x : b) sum = (uint8_t)(sum + x);
        if (sum != 0) throw HexError(where + ": wrong checksum (the file is damaged)" + REBUILD);
        uint32_t address = base + (uint32_t)(b[1] << 8 | b[2]);
        switch (b[3]) {
        case 0x00:
            if (flash.size() < address + b[0]) flash.resize(address + b[0], 0xFF);
            for (unsigned i = 0; i < b[0]; i++) flash[address + i] = b[4 + i];
            break;
        case 0x01: return flash;
        case 0x02: base = (uint32_t)(b[4] << 8 | b[5]) << 4; break;
        case 0x04: base = (uint32_t)(b[4] << 8 | b[5]) << 16; break;
        default: break; // 03, 05: a start address, which a bootloader ignores
        }
        if (flash.size() > (1u << 24))
            throw HexError(where + ": an address past 16 MB; this is not a microcontroller's image" + REBUILD);
    }
    throw HexError(file.string() + ": no end-of-file record (:00000001FF); the file was cut short" + REBUILD);
}

}  // namespace openswarm
