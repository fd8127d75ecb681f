// The dsPIC e-puck's camera logic on the host (ports/epuck/dspic/src:
// po3030k_setup.c, camera_frame.c): the registers for the classifier's
// frame, applied to a model PO3030K whose register file takes each write
// and which then sends an image as the sensor would (its window, its
// subsampling, a lead pixel and row before the first wanted ones); the
// test reads each line as camera_capture.S does, by the capture plan, and
// checks the frame assembled and the classifier's judgement of it.
#include <gtest/gtest.h>

#include <functional>
#include <vector>

extern "C" {
#include "camera_frame.h"
#include "po3030k_setup.h"
}

namespace {

constexpr unsigned ORIGIN_X = 210, ORIGIN_Y = 7; // the array's first column, row

// A PO3030K: 256 registers; 16-bit values high byte first.
struct Po3030k {
    uint8_t reg[256] = {};
    void take(const po3030k_write *w, unsigned n) {
        for (unsigned i = 0; i < n; i++) reg[w[i].reg] = w[i].value;
    }
    unsigned pair(uint8_t r) const { return unsigned(reg[r]) << 8 | reg[r + 1]; }
    unsigned factor() const { return reg[0x20] == 0x33 ? 4 : reg[0x20] == 0x11 ? 2 : 1; }
    // The window's first column and row in array pixels (X1 counts from the
    // column before it; VSYNC starts at Y1).
    int first_x() const { return int(pair(0x08) + 1) - int(ORIGIN_X); }
    int first_y() const { return int(pair(0x0A)) - int(ORIGIN_Y); }
    // Output line n after VSYNC (n = 1 the first one after the lead row):
    // from the lead pixel on, two bytes a pixel, high byte first.
    std::vector<uint8_t> line(unsigned n, const std::function<uint16_t(int, int)> &image) const {
        std::vector<uint8_t> bytes;
        int y = first_y() + int(n * factor());
        for (int x = first_x(); x < int(640); x += int(factor())) {
            uint16_t v = image(x, y);
            bytes.push_back(uint8_t(v >> 8));
            bytes.push_back(uint8_t(v));
        }
        return bytes;
    }
};

std::vector<std::vector<uint16_t>> delivered;
std::vector<epuck_camera_frame> frames;
void on_frame(const epuck_camera_frame *f) {
    frames.push_back(*f);
    delivered.emplace_back(f->pixels, f->pixels + f->width * f->height);
}

class DspicCamera : public ::testing::Test {
protected:
    Po3030k sensor;
    po3030k_capture plan{};
    void SetUp() override {
        delivered.clear();
        frames.clear();
        po3030k_write w[PO3030K_SETUP_WRITES];
        ASSERT_TRUE(po3030k_plan(&po3030k_classifier_frame, w, &plan));
        sensor.take(w, PO3030K_SETUP_WRITES);
        ASSERT_TRUE(camera_frame_init(plan.columns, plan.rows, plan.columns, on_frame));
    }
    // camera_capture.S on one line: from the first sample (the pixel after
    // the lead one), 2 bytes taken, then skip_pixels pixels passed, columns
    // times; its 16 + delay_repeat cycles a taken pixel at 8 a byte.
    void read_row(const std::vector<uint8_t> &line) {
        uint8_t *to = camera_frame_row();
        if (to == nullptr) return;
        ASSERT_EQ(16u + plan.delay_repeat, 16u * (1u + plan.skip_pixels)) << "the loop keeps the sensor's pace";
        size_t at = 2; // the lead pixel's two slots are gone by the first sample
        for (unsigned c = 0; c < plan.columns; c++, at += 2 + 2 * plan.skip_pixels) {
            ASSERT_LT(at + 1, line.size());
            *to++ = line[at];
            *to++ = line[at + 1];
        }
        camera_frame_row_done();
    }
    // A whole sensor frame: VSYNC, then lines; Timer4 interrupts on the
    // first line after VSYNC and every href_per_row-th after it.
    void sensor_frame(const std::function<uint16_t(int, int)> &image, unsigned lines = 120) {
        camera_frame_vsync();
        for (unsigned n = 1; n <= lines; n++)
            if ((n - 1) % plan.href_per_row == 0) read_row(sensor.line(n, image));
    }
};

TEST_F(DspicCamera, TheSensorIsSetForTheCentral160SubsampledByFourInRgb565) {
    EXPECT_EQ(0x08, sensor.reg[0x4E]) << "RGB565";
    EXPECT_EQ(0x33, sensor.reg[0x20]) << "QQVGA: the sensor takes every 4th pixel and row";
    EXPECT_EQ(0x20, sensor.reg[0x1D]) << "pixel clock divider 4 (a byte every 8 cycles)";
    EXPECT_EQ(240 - 4, sensor.first_x()) << "one output pixel of lead before column 240";
    EXPECT_EQ(160 - 4, sensor.first_y()) << "VSYNC a row before row 160";
    EXPECT_EQ(445u, sensor.pair(0x08));
    EXPECT_EQ(851u, sensor.pair(0x0C)) << "to the array's right edge";
    EXPECT_EQ(488u, sensor.pair(0x0E)) << "to the bottom";
    EXPECT_EQ(163u, sensor.pair(0xA5)) << "VSYNC from the lead row";
    EXPECT_EQ(487u, sensor.pair(0xA7));
    EXPECT_EQ(447u, sensor.pair(0xA9)) << "VSYNC after that row's HREF";
}

TEST_F(DspicCamera, TheInterruptTakesEveryOtherPixelAndLineOf20x20) {
    EXPECT_EQ(20, plan.columns);
    EXPECT_EQ(20, plan.rows);
    EXPECT_EQ(2, plan.href_per_row);
    EXPECT_EQ(1, plan.skip_pixels);
    EXPECT_EQ(16u, plan.delay_repeat) << "one skipped pixel: 16 cycles";
}

TEST_F(DspicCamera, AFrameIsTheCentralWindowEveryEighthPixel) {
    auto image = [](int x, int y) { return uint16_t(x * 97 + y * 31); };
    sensor_frame(image);
    ASSERT_EQ(1u, delivered.size());
    EXPECT_EQ(20, frames[0].width);
    EXPECT_EQ(20, frames[0].height);
    EXPECT_EQ(20, frames[0].window) << "the frame is the classifier's window";
    for (int r = 0; r < 20; r++)
        for (int c = 0; c < 20; c++)
            ASSERT_EQ(image(240 + 8 * c, 160 + 8 * r), delivered[0][r * 20 + c]) << "row " << r << " column " << c;
    EXPECT_EQ(1u, camera_frame_delivered());
    EXPECT_EQ(0u, camera_frame_cut_short());
}

TEST_F(DspicCamera, BytesBecomePixelsHighByteFirst) {
    sensor_frame([](int, int) { return uint16_t(0xF800); });
    ASSERT_EQ(1u, delivered.size());
    EXPECT_EQ(0xF800, delivered[0][0]) << "0xF8 then 0x00 is red";
    EXPECT_EQ(EPUCK_COLOUR_RED, epuck_colour_of(delivered[0][210]));
}

TEST_F(DspicCamera, AFrameCutShortByVsyncIsDroppedAndCounted) {
    auto grey = [](int, int) { return uint16_t(0x8410); };
    sensor_frame(grey, 15); // 8 rows, then the next VSYNC
    EXPECT_TRUE(delivered.empty());
    sensor_frame(grey);
    EXPECT_EQ(1u, delivered.size());
    EXPECT_EQ(1u, camera_frame_cut_short());
    EXPECT_EQ(1u, camera_frame_delivered());
}

TEST_F(DspicCamera, NoRowIsTakenBeforeTheFirstVsyncNorAfterTheFrameIsWhole) {
    EXPECT_EQ(nullptr, camera_frame_row());
    EXPECT_FALSE(camera_frame_row_done()) << "a row before any VSYNC is not counted";
    sensor_frame([](int, int) { return uint16_t(0); });
    EXPECT_EQ(nullptr, camera_frame_row()) << "Timer4 stops: the rest of the sensor's lines are not read";
    EXPECT_FALSE(camera_frame_row_done());
    EXPECT_EQ(1u, delivered.size());
    camera_frame_vsync();
    EXPECT_NE(nullptr, camera_frame_row());
    EXPECT_EQ(0u, camera_frame_cut_short()) << "a whole frame then a VSYNC is no cut";
}

// The same classifier as on the e-puck2: a red object filling the window's
// middle band is an object; green is a robot; a white wall nothing.
TEST_F(DspicCamera, TheSharedClassifierJudgesTheFrame) {
    struct Case {
        uint16_t centre;
        epuck_seen expected;
    } cases[] = {{0xF800, EPUCK_SEEN_OBJECT}, {0x07E0, EPUCK_SEEN_ROBOT}, {0xFFFF, EPUCK_SEEN_NOTHING}};
    for (const Case &k : cases) {
        delivered.clear();
        frames.clear();
        // Outside the central 160 x 160 the scene is red: it must not count.
        sensor_frame([&](int x, int y) {
            bool inside = x >= 240 && x < 400 && y >= 160 && y < 320;
            return inside ? k.centre : uint16_t(0xF800);
        });
        ASSERT_EQ(1u, frames.size());
        epuck_camera_frame f = frames[0];
        f.pixels = delivered[0].data();
        epuck_seen seen;
        ASSERT_TRUE(epuck_classify_frame(&f, &seen));
        EXPECT_EQ(k.expected, seen) << std::hex << k.centre;
    }
}

TEST(DspicCameraPlan, OtherZoomsUseTheSensorsOwnSubsamplingWhereTheyCan) {
    po3030k_write w[PO3030K_SETUP_WRITES];
    po3030k_capture c;
    struct Case {
        uint8_t zoom, sampling, speed, href, skip;
    } cases[] = {{4, 0x33, 0x20, 1, 0}, {2, 0x11, 0x30, 1, 0}, {6, 0x11, 0x30, 3, 2}, {3, 0x44, 0x40, 3, 2}};
    for (const Case &k : cases) {
        po3030k_request r = {0, 0, uint16_t(12u * k.zoom), uint16_t(12u * k.zoom), k.zoom};
        ASSERT_TRUE(po3030k_plan(&r, w, &c)) << int(k.zoom);
        Po3030k s;
        s.take(w, PO3030K_SETUP_WRITES);
        EXPECT_EQ(k.sampling, s.reg[0x20]) << int(k.zoom);
        EXPECT_EQ(k.speed, s.reg[0x1D]) << int(k.zoom);
        EXPECT_EQ(k.href, c.href_per_row) << int(k.zoom);
        EXPECT_EQ(k.skip, c.skip_pixels) << int(k.zoom);
        EXPECT_EQ(16u * k.skip, c.delay_repeat) << int(k.zoom);
        EXPECT_EQ(12, c.columns);
        EXPECT_EQ(-int(s.factor()), s.first_x()) << "the lead in the sensor's margin";
    }
}

TEST(DspicCameraPlan, ImpossibleRequestsAreRefused) {
    po3030k_write w[PO3030K_SETUP_WRITES];
    po3030k_capture c;
    po3030k_request zero = {0, 0, 160, 160, 0}, uneven = {0, 0, 161, 160, 8},
                    outside = {500, 0, 160, 160, 8}, too_many = {0, 0, 640, 8, 2};
    EXPECT_FALSE(po3030k_plan(&zero, w, &c));
    EXPECT_FALSE(po3030k_plan(&uneven, w, &c));
    EXPECT_FALSE(po3030k_plan(&outside, w, &c));
    EXPECT_FALSE(po3030k_plan(&too_many, w, &c)) << "320 columns";
}

TEST(DspicCameraFrame, AFrameOver800BytesIsRefused) {
    EXPECT_FALSE(camera_frame_init(21, 20, 21, on_frame));
    EXPECT_FALSE(camera_frame_init(0, 20, 0, on_frame));
    EXPECT_TRUE(camera_frame_init(20, 20, 20, on_frame));
}

} // namespace
