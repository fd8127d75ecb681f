// The camera classifier's window and colour rule (ports/epuck/src/
// camera_classifier.c): the original OpenSwarm classifier's 24 points and
// nearest-colour match by default, this project's earlier band when built
// with EPUCK_CLASSIFIER_BAND. Frames here are the window alone (20 x 20,
// one pixel a grid cell, as the dsPIC e-puck's), so each test paints
// exactly the cells one window samples and the other does not.
#include <gtest/gtest.h>

#include <vector>

extern "C" {
#include "openswarm/epuck.h"
}

namespace {

constexpr uint16_t rgb565(unsigned r, unsigned g, unsigned b) {
    return (uint16_t)(((r >> 3) << 11) | ((g >> 2) << 5) | (b >> 3));
}
constexpr uint16_t WHITE = rgb565(248, 252, 248), RED = rgb565(248, 0, 0);

struct Window {
    std::vector<uint16_t> pixels = std::vector<uint16_t>(20 * 20, WHITE);
    Window &paint(unsigned x0, unsigned x1, unsigned y0, unsigned y1, uint16_t c) {
        for (unsigned y = y0; y <= y1; y++)
            for (unsigned x = x0; x <= x1; x++) pixels[y * 20 + x] = c;
        return *this;
    }
    epuck_seen seen() const {
        epuck_camera_frame f = {pixels.data(), 20, 20, 20};
        epuck_seen s = EPUCK_SEEN_NOTHING;
        EXPECT_TRUE(epuck_classify_frame(&f, &s));
        return s;
    }
};

#ifdef EPUCK_CLASSIFIER_BAND
constexpr bool ORIGINAL = false;
#else
constexpr bool ORIGINAL = true;
#endif
const epuck_seen IF_ORIGINAL_OBJECT = ORIGINAL ? EPUCK_SEEN_OBJECT : EPUCK_SEEN_NOTHING;
const epuck_seen IF_BAND_OBJECT = ORIGINAL ? EPUCK_SEEN_NOTHING : EPUCK_SEEN_OBJECT;

TEST(EpuckClassifier, TheBandsOuterColumnsAreOutsideTheOriginalsWindow) {
    // Columns 2..3 and 17..18, every row: the band samples columns 2 and 17
    // (8 points), the original only columns 6..15.
    EXPECT_EQ(IF_BAND_OBJECT, Window().paint(2, 3, 0, 19, RED).paint(17, 18, 0, 19, RED).seen());
}

TEST(EpuckClassifier, TheOriginalsHighRowsAreAboveTheBand) {
    // Rows 4..7 across the middle columns: the original samples rows 4 and
    // 6 (8 points), the band only rows 8..11.
    EXPECT_EQ(IF_ORIGINAL_OBJECT, Window().paint(5, 15, 4, 7, RED).seen());
}

TEST(EpuckClassifier, TheOriginalsWindowLeansRightOfCentre) {
    // Columns 6, 9, 12, 15: one column right of the window's centre line
    // (9.5), so columns 14..15 meet it and their mirror image 4..5 does not
    // (the band samples column 14 and column 5).
    EXPECT_EQ(EPUCK_SEEN_OBJECT, Window().paint(14, 15, 0, 19, RED).seen());
    EXPECT_EQ(IF_BAND_OBJECT, Window().paint(4, 5, 0, 19, RED).seen());
}

TEST(EpuckClassifier, ADimGreenRobotIsARobotToTheOriginal) {
    // (0, 40, 0) is the original's own green; the band's thresholds call
    // anything whose brightest channel is under 64 dark, and dark counts as
    // an object.
    epuck_seen seen = Window().paint(0, 19, 0, 19, rgb565(0, 40, 0)).seen();
    EXPECT_EQ(ORIGINAL ? EPUCK_SEEN_ROBOT : EPUCK_SEEN_OBJECT, seen);
}

TEST(EpuckClassifier, TheNearestColourIsTheOriginalsMatch) {
    EXPECT_EQ(EPUCK_COLOUR_WHITE, epuck_colour_nearest(WHITE));
    EXPECT_EQ(EPUCK_COLOUR_WHITE, epuck_colour_nearest(rgb565(100, 80, 80))) << "a dim wall";
    EXPECT_EQ(EPUCK_COLOUR_RED, epuck_colour_nearest(RED));
    EXPECT_EQ(EPUCK_COLOUR_RED, epuck_colour_nearest(rgb565(64, 8, 8))) << "a dark red";
    EXPECT_EQ(EPUCK_COLOUR_GREEN, epuck_colour_nearest(rgb565(0, 252, 0)));
    EXPECT_EQ(EPUCK_COLOUR_DARK, epuck_colour_nearest(rgb565(8, 8, 8)));
    // (40, 20, 0) is 60 from dark, green and red alike: a tie goes to the
    // first of dark, green, red, white.
    EXPECT_EQ(EPUCK_COLOUR_DARK, epuck_colour_nearest(rgb565(40, 20, 0)));
}

} // namespace
