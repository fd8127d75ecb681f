// A native robot's RAM image copied and summed in one pass
// (sim/src/native/native_image_copy.c): the copy is exact, and the sum
// finds what a stray write from another robot's code would leave in a
// saved image - any byte changed, words swapped - at any length, the
// zero-padded tail included.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <utility>
#include <vector>

extern "C" {
#include "native/native_image_copy.h"
}

namespace {

std::vector<uint8_t> random_image(size_t n, unsigned seed) {
    std::mt19937 rng(seed);
    std::vector<uint8_t> image(n);
    for (auto &b : image) b = (uint8_t)rng();
    return image;
}

uint64_t sum_of(const std::vector<uint8_t> &image) {
    std::vector<uint8_t> copy(image.size() + 1);
    return native_image_copy_summed(copy.data(), image.data(), image.size());
}

const size_t lengths[] = {1, 7, 63, 64, 65, 127, 1712, 2048};

}  // namespace

TEST(NativeImageCopy, CopiesEveryByteAndNoMore) {
    for (size_t n : lengths) {
        auto image = random_image(n, (unsigned)n);
        std::vector<uint8_t> copy(n + 64, 0xA5);
        native_image_copy_summed(copy.data(), image.data(), n);
        EXPECT_TRUE(std::equal(image.begin(), image.end(), copy.begin())) << n << " bytes";
        for (size_t i = n; i < copy.size(); i++) ASSERT_EQ(copy[i], 0xA5) << "byte " << i << " past " << n;
    }
}

TEST(NativeImageCopy, TheSameImageSumsTheSame) {
    auto image = random_image(1712, 1);
    EXPECT_EQ(sum_of(image), sum_of(image));
}

TEST(NativeImageCopy, AnyChangedByteChangesTheSum) {
    for (size_t n : lengths) {
        auto image = random_image(n, 2);
        uint64_t before = sum_of(image);
        for (size_t i = 0; i < n; i++)
            for (uint8_t bit : {(uint8_t)1, (uint8_t)0x80}) {
                image[i] ^= bit;
                ASSERT_NE(sum_of(image), before) << "byte " << i << " of " << n << ", bit " << (int)bit;
                image[i] ^= bit;
            }
    }
}

TEST(NativeImageCopy, SwappedWordsChangeTheSum) {
    auto image = random_image(1712, 3);
    uint64_t before = sum_of(image);
    // Two 8-byte words of one lane (64 bytes apart) and of neighbouring lanes.
    for (size_t gap : {(size_t)8, (size_t)64, (size_t)640})
        for (size_t at = 0; at + gap + 8 <= image.size(); at += 136) {
            for (size_t k = 0; k < 8; k++) std::swap(image[at + k], image[at + gap + k]);
            ASSERT_NE(sum_of(image), before) << "words at " << at << " and " << at + gap;
            for (size_t k = 0; k < 8; k++) std::swap(image[at + k], image[at + gap + k]);
        }
}
