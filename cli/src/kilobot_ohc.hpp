// The Kilobot overhead controller's serial protocol, as KiloGUI speaks it
// to the controller's FTDI port (38400 baud, 8N1): fixed packets of 132
// bytes - 0x55, a kind, 129 bytes of argument, and the XOR of the 131
// bytes before it. The controller sends each message or boot page on to
// the robots by infrared; it answers nothing.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "serial_port.hpp"

namespace openswarm {

constexpr unsigned OHC_BAUD = 38400;
// The ATmega328P's flash page (SPM_PAGESIZE): the bootloader writes one
// page per boot packet.
constexpr unsigned OHC_PAGE_BYTES = 128;
// KiloGUI never sends more pages than this; the bootloader's own 4 KB sit
// above 0x7000.
constexpr unsigned OHC_MAX_PAGES = 220;

using OhcPacket = std::array<uint8_t, OHC_PAGE_BYTES + 4>;

// The robots' system messages the controller repeats until the next
// packet (kilolib's message types).
enum class OhcMessage : uint8_t { boot = 0x80, program_size = 0x82, run = 0x88 };

// A packet that has the controller repeat a message of kind type, its
// first data byte argument.
OhcPacket ohc_message(OhcMessage type, uint8_t argument = 0);
// A packet carrying flash page number page (128 bytes from flash at
// page * 128, 0xFF past its end).
OhcPacket ohc_boot_page(const std::vector<uint8_t> &flash, unsigned page);
// The packet that stops the controller's repeating.
OhcPacket ohc_stop();

struct OhcUpload {
    double page_gap = 0.13;   // seconds between packets: KiloGUI's, the time
                              // the controller takes to send a page by IR
    double boot_wait = 1.0;   // after Bootload, for the robots to reset into it
    unsigned rounds = 1;      // the whole image again, for robots that missed a page
    double timeout = 5.0;     // a port that takes no bytes this long: no controller
};

// Sends Bootload, then rounds x (the page count, every page), then Stop.
// on_page(round, page, pages) after each page. Throws SerialError.
void upload_through_ohc(SerialPort &port, const std::vector<uint8_t> &flash, const OhcUpload &how,
                        void (*on_page)(unsigned round, unsigned page, unsigned pages));

}  // namespace openswarm
