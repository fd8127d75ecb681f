/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* "eeprom": bytes every Kilobot's EEPROM holds when it starts, at
 * addresses from 0x100 on (kilolib's calibration and uid lie below). A
 * sweep writes an app's "at": "eeprom" values here, so each run sets them
 * without a build (docs/world.md, docs/openswarm-json.md). */
#include <string>

#include "world/world_file_reader.hpp"

namespace world_file {

namespace {

const std::string example = "\"eeprom\": [{\"address\": 256, \"bytes\": [234, 1, 0, 0]}]";

std::string hex(long address) {
    char text[16];
    snprintf(text, sizeof text, "0x%03lX", (unsigned long)address);
    return text;
}

}  // namespace

void Reader::eeprom(const Node &n, world_spec &w) const {
    if (kind_ != WORLD_ROBOT_KILOBOT)
        fail(n, "the robots' EEPROM is a Kilobot's; " + robots_plural_ + " have none here: drop \"eeprom\"");
    if (!n->is_array()) fail(n, "expected a list of {\"address\", \"bytes\"}, found " + found(*n) + "; e.g. " + example);
    for (size_t k = 0; k < n->size(); k++) {
        Node e = item(n, k);
        object(e, {"address", "bytes"}, example);
        long address = whole(need(e, "address", example), WORLD_EEPROM_APP_START, WORLD_EEPROM_BYTES - 1,
                             "an address in the app's part of the EEPROM, 256..1023 (kilolib keeps its "
                             "calibration and uid below 256)",
                             "\"address\": 256");
        Node bytes = need(e, "bytes", example);
        if (!bytes->is_array() || bytes->empty())
            fail(bytes, "expected a list of bytes 0..255, found " + found(*bytes) + "; e.g. \"bytes\": [234, 1, 0, 0]");
        if (address + (long)bytes->size() > WORLD_EEPROM_BYTES)
            fail(bytes, "no room: " + std::to_string(bytes->size()) + " bytes from " + hex(address) +
                            " pass the EEPROM's end (0x3FF); start them lower");
        for (size_t b = 0; b < bytes->size(); b++) {
            long at = address + (long)b;
            uint8_t v = (uint8_t)whole(item(bytes, b), 0, 255, "a byte", "234");
            if (w.eeprom_given[at])
                fail(item(bytes, b), "the byte at " + hex(at) + " is given twice (by two items of \"eeprom\"): "
                                     "keep one");
            w.eeprom[at] = v;
            w.eeprom_given[at] = 1;
        }
    }
}

}  // namespace world_file
