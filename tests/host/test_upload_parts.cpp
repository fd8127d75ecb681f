// The parts of `openswarm upload` that need no port: the Intel HEX reader
// and the overhead controller's packets (the whole upload is e2e.upload_kilobot).
#include <gtest/gtest.h>

#include <fstream>

#include "../../cli/src/intel_hex.hpp"
#include "../../cli/src/kilobot_ohc.hpp"

using namespace openswarm;

namespace {

// A HEX file holding text for as long as the expression that reads it
// (removed after, so runs leave nothing in /tmp).
struct hex_file {
    std::filesystem::path path;
    explicit hex_file(const std::string &text)
        : path(std::filesystem::temp_directory_path() /
               ("upload_parts_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".hex")) {
        std::ofstream(path) << text;
    }
    ~hex_file() {
        std::error_code ignored;
        std::filesystem::remove(path, ignored);
    }
    operator const std::filesystem::path &() const { return path; }
};

uint8_t xor_of(const OhcPacket &p) {
    uint8_t x = 0;
    for (size_t i = 0; i + 1 < p.size(); i++) x ^= p[i];
    return x;
}

}  // namespace

TEST(IntelHex, FillsGapsWithErasedFlashAndFollowsExtendedAddresses) {
    // 2 bytes at 0x0000, 1 at 0x0004; then 1 at 0x10000 + 0x0001 through a linear address record
    auto flash = read_intel_hex(hex_file(":020000000102FB\n:01000400AA51\n:00000001FF\n"));
    ASSERT_EQ(flash.size(), 5u);
    EXPECT_EQ(flash[0], 0x01);
    EXPECT_EQ(flash[1], 0x02);
    EXPECT_EQ(flash[2], 0xFF);
    EXPECT_EQ(flash[3], 0xFF);
    EXPECT_EQ(flash[4], 0xAA);
    auto high = read_intel_hex(hex_file(":020000040001F9\r\n:0100010055A9\r\n:00000001FF\r\n"));
    ASSERT_EQ(high.size(), 0x10002u);
    EXPECT_EQ(high[0x10001], 0x55);
}

TEST(IntelHex, NamesTheLineOfABadRecord) {
    try {
        read_intel_hex(hex_file(":020000000102FB\n:01000400AA52\n:00000001FF\n"));
        FAIL() << "a bad checksum was read";
    } catch (const HexError &e) {
        EXPECT_NE(std::string(e.what()).find(".hex:2: wrong checksum"), std::string::npos) << e.what();
    }
    EXPECT_THROW(read_intel_hex(hex_file(":020000000102FB\n")), HexError);   // no end record
    EXPECT_THROW(read_intel_hex(hex_file(":0200000001G2FB\n")), HexError);   // not hex
    EXPECT_THROW(read_intel_hex(hex_file(":030000000102FB\n")), HexError);   // length byte lies
}

TEST(OhcPackets, CarryAPageWithItsNumberAndXor) {
    std::vector<uint8_t> flash(200);
    for (size_t i = 0; i < flash.size(); i++) flash[i] = (uint8_t)i;
    OhcPacket second = ohc_boot_page(flash, 1);
    EXPECT_EQ(second[0], 0x55);
    EXPECT_EQ(second[1], 4); // a boot page
    EXPECT_EQ(second[2], 1);
    EXPECT_EQ(second[3], 128);               // flash[128]
    EXPECT_EQ(second[3 + 71], 199);          // the last byte of the image
    EXPECT_EQ(second[3 + 72], 0xFF);         // past it: erased flash
    EXPECT_EQ(second.back(), xor_of(second));
}

TEST(OhcPackets, MessagesPutTheTypeAfterNineDataBytes) {
    OhcPacket size = ohc_message(OhcMessage::program_size, 70);
    EXPECT_EQ(size[1], 2); // forward a message
    EXPECT_EQ(size[2], 70);
    EXPECT_EQ(size[11], 0x82);
    EXPECT_EQ(size.back(), xor_of(size));
    OhcPacket stop = ohc_stop();
    EXPECT_EQ(stop[1], 0);
    EXPECT_EQ(stop.back(), 0x55); // the XOR of the header alone
}
