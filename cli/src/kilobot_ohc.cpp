#include "kilobot_ohc.hpp"

#include <chrono>
#include <thread>

namespace openswarm {

namespace {

constexpr uint8_t HEADER = 0x55;
// The packet's kind (byte 1).
enum Kind : uint8_t { STOP = 0, FORWARD_MESSAGE = 2, BOOT_PAGE = 4 };
// A forwarded message's 9 data bytes start at byte 2; its type is byte 11.
constexpr size_t MESSAGE_TYPE_AT = 11;

OhcPacket sealed(OhcPacket p) {
    uint8_t check = 0;
    for (size_t i = 0; i + 1 < p.size(); i++) check ^= p[i];
    p.back() = check;
    return p;
}

OhcPacket blank(Kind kind) {
    OhcPacket p{};
    p[0] = HEADER;
    p[1] = kind;
    return p;
}

void send(SerialPort &port, const OhcPacket &p, const OhcUpload &how) {
    port.write_all(p.data(), p.size(), how.timeout);
    std::this_thread::sleep_for(std::chrono::duration<double>(how.page_gap));
}

}  // namespace

OhcPacket ohc_message(OhcMessage type, uint8_t argument) {
    OhcPacket p = blank(FORWARD_MESSAGE);
    p[2] = argument;
    p[MESSAGE_TYPE_AT] = (uint8_t)type;
    return sealed(p);
}

OhcPacket ohc_boot_page(const std::vector<uint8_t> &flash, unsigned page) {
    OhcPacket p = blank(BOOT_PAGE);
    p[2] = (uint8_t)page;
    for (unsigned i = 0; i < OHC_PAGE_BYTES; i++) {
        size_t at = (size_t)page * OHC_PAGE_BYTES + i;
        p[3 + i] = at < flash.size() ? flash[at] : 0xFF;
    }
    return sealed(p);
}

OhcPacket ohc_stop() { return sealed(blank(STOP)); }

void upload_through_ohc(SerialPort &port, const std::vector<uint8_t> &flash, const OhcUpload &how,
                        void (*on_page)(unsigned, unsigned, unsigned)) {
    unsigned pages = (unsigned)((flash.size() + OHC_PAGE_BYTES - 1) / OHC_PAGE_BYTES);
    port.write_all(ohc_message(OhcMessage::boot).data(), sizeof(OhcPacket), how.timeout);
    std::this_thread::sleep_for(std::chrono::duration<double>(how.boot_wait));
    for (unsigned round = 1; round <= how.rounds; round++) {
        send(port, ohc_message(OhcMessage::program_size, (uint8_t)pages), how);
        for (unsigned page = 0; page < pages; page++) {
            send(port, ohc_boot_page(flash, page), how);
            on_page(round, page, pages);
        }
    }
    port.write_all(ohc_stop().data(), sizeof(OhcPacket), how.timeout);
}

}  // namespace openswarm
