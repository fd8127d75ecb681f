// The e-puck's device layer (ports/epuck/src) on the host port, with a
// board of the test's own behind ports/epuck/src/epuck_board.h: what the
// processors make of commands and readings, and what reaches the board.
#include "kernel_fixture.hpp"

#include <cstring>

extern "C" {
#include "../../ports/epuck/src/epuck_board.h"
#include "openswarm/epuck.h"
}

// ---- the test's board: each call noted in the trace ----
extern "C" {
void epuck_board_set_wheels(int16_t left, int16_t right) {
    note("wheels " + std::to_string(left) + " " + std::to_string(right));
}
void epuck_board_set_ring_leds(uint8_t mask) { note("ring " + std::to_string(mask)); }
void epuck_board_set_body_led(bool on) { note(std::string("body ") + (on ? "on" : "off")); }
void epuck_board_set_front_led(bool on) { note(std::string("front ") + (on ? "on" : "off")); }
void epuck_board_set_rgb_leds(uint8_t rgb) { note("rgb " + std::to_string(rgb)); }
void epuck_board_start(void) { note("start"); }
}

namespace {

class Epuck : public KernelTest {
protected:
    // Boots with the devices registered; the board's start is the first note.
    void boot_devices(std::function<void()> more = [] {}) {
        boot([more] {
            EXPECT_STATUS(SYS_OK, epuck_devices_init());
            more();
        });
        settle();
    }

    static void send(sys_event_id event, const void *value, uint8_t size) {
        irq([&] { Sys_Send_Event(event, value, size); });
        settle();
    }

    template <typename T> static T event_value(sys_event_id event) {
        T value{};
        irq([&] { Sys_Get_EventData(event, &value, sizeof value, nullptr); });
        return value;
    }
};

TEST_F(Epuck, DevicesRegisterWithTheirValuesSizesAndStartTheBoard) {
    sys_stats before{};
    boot_devices([&] { Sys_Get_Stats(&before); });
    EXPECT_EQ("start", joined());
    EXPECT_EQ(0u, stats().event_data_full);
    EXPECT_EQ(0u, stats().device_table_full);
}

TEST_F(Epuck, WheelCommandsAreClampedAndRampedToWhatTheSteppersFollow) {
    boot_devices();
    epuck_wheel_speeds want = {2000, -2000};
    for (int i = 0; i < 6; i++) send(EPUCK_EVENT_WHEELS, &want, sizeof want);
    EXPECT_EQ("start wheels 200 -200 wheels 400 -400 wheels 600 -600 wheels 800 -800 "
              "wheels 1000 -1000 wheels 1000 -1000",
              joined());
    epuck_wheel_speeds stop = {0, 0};
    send(EPUCK_EVENT_WHEELS, &stop, sizeof stop);
    EXPECT_EQ("wheels 800 -800", trace().back()) << "a stop is ramped too";
}

TEST_F(Epuck, WheelLimitsAreTheProcessorsParameters) {
    static epuck_wheel_limits slow = {300, 1000};
    boot_devices([] { Sys_Set_Processor(&epuck_wheels, epuck_wheels_limited, &slow); });
    epuck_wheel_speeds want = {800, -100};
    send(EPUCK_EVENT_WHEELS, &want, sizeof want);
    EXPECT_EQ("wheels 300 -100", trace().back());
    uint8_t odd[3] = {};
    send(EPUCK_EVENT_WHEELS, odd, sizeof odd);
    EXPECT_EQ("wheels 300 -100", trace().back()) << "not a command: the board hears nothing";
    EXPECT_EQ(1u, epuck_wheels.rejected);
}

TEST_F(Epuck, LedsReachTheBoard) {
    boot_devices();
    uint8_t ring = 0x81, on = 1, off = 0, rgb = EPUCK_RGB(3, 0, 1);
    send(EPUCK_EVENT_RING_LEDS, &ring, 1);
    send(EPUCK_EVENT_BODY_LED, &on, 1);
    send(EPUCK_EVENT_FRONT_LED, &off, 1);
    send(EPUCK_EVENT_RGB_LEDS, &rgb, 1);
    EXPECT_EQ("start ring 129 body on front off rgb 19", joined());
}

TEST_F(Epuck, ProximityIsAmbientAndWhatThePulseAdded) {
    boot_devices();
    epuck_proximity_samples s{};
    for (int i = 0; i < EPUCK_PROXIMITY_SENSORS; i++) {
        s.off[i] = (uint16_t)(3000 + i);      // the receiver's output, emitters off
        s.pulsed[i] = (uint16_t)(3000 - 100 * i); // lower: more light came back
    }
    s.pulsed[7] = 3100; // above the ambient: noise, nothing reflected
    irq([&] { epuck_proximity_arrived(&s); });
    settle();
    auto r = event_value<epuck_proximity_reading>(EPUCK_EVENT_PROXIMITY);
    for (int i = 0; i < 7; i++) {
        EXPECT_EQ(3000 + i, r.ambient[i]) << "sensor " << i;
        EXPECT_EQ(101 * i, r.reflected[i]) << "sensor " << i;
    }
    EXPECT_EQ(0, r.reflected[7]);
}

TEST_F(Epuck, TheSelectorIsAnEventWhenItTurns) {
    std::vector<int> seen;
    static std::vector<int> *positions;
    positions = &seen;
    boot_devices([] {
        Sys_Subscribe_to_Event(
            EPUCK_EVENT_SELECTOR, SYS_PID_SYSTEM,
            [](sys_pid, sys_event_id, const sys_event_data *d) {
                positions->push_back(*(const uint8_t *)d->value);
                return true;
            },
            nullptr);
    });
    for (uint8_t p : {3, 3, 3, 5, 5, 0x1F}) {
        irq([p] { epuck_selector_arrived(p); });
        settle();
    }
    EXPECT_EQ((std::vector<int>{3, 5, 15}), seen) << "changes only; 4 bits";
}

// ---- the camera's virtual sensor ----
constexpr uint16_t rgb565(unsigned r, unsigned g, unsigned b) {
    return (uint16_t)(((r * 31 / 255) << 11) | ((g * 63 / 255) << 5) | (b * 31 / 255));
}
constexpr uint16_t WHITE = rgb565(240, 240, 240), RED = rgb565(200, 30, 30),
                   GREEN = rgb565(40, 190, 40), DARK = rgb565(20, 20, 20),
                   GREY = rgb565(128, 128, 128);

TEST(EpuckColour, PixelsMatchTheFourColoursOrNone) {
    EXPECT_EQ(EPUCK_COLOUR_WHITE, epuck_colour_of(WHITE));
    EXPECT_EQ(EPUCK_COLOUR_RED, epuck_colour_of(RED));
    EXPECT_EQ(EPUCK_COLOUR_GREEN, epuck_colour_of(GREEN));
    EXPECT_EQ(EPUCK_COLOUR_DARK, epuck_colour_of(DARK));
    EXPECT_EQ(EPUCK_COLOUR_OTHER, epuck_colour_of(GREY));
    EXPECT_EQ(EPUCK_COLOUR_OTHER, epuck_colour_of(rgb565(200, 200, 30))) << "yellow";
}

struct Frame {
    uint16_t width, height;
    std::vector<uint16_t> pixels;
    Frame(uint16_t w, uint16_t h, uint16_t fill) : width(w), height(h), pixels((size_t)w * h, fill) {}
    // A rectangle of colour c, in fractions of the frame.
    Frame &paint(double x0, double y0, double x1, double y1, uint16_t c) {
        for (unsigned y = (unsigned)(y0 * height); y < (unsigned)(y1 * height); y++)
            for (unsigned x = (unsigned)(x0 * width); x < (unsigned)(x1 * width); x++)
                pixels[(size_t)y * width + x] = c;
        return *this;
    }
    uint8_t seen() const {
        epuck_camera_frame f = {pixels.data(), width, height, 0};
        uint8_t out = 0xFF;
        sys_device dev{};
        EXPECT_EQ(1, epuck_camera_classifier(&dev, &f, sizeof f, &out, 1));
        return out;
    }
};

TEST(EpuckCamera, ClassifiesWhatIsInFrontOfTheRobot) {
    EXPECT_EQ(EPUCK_SEEN_NOTHING, Frame(640, 480, WHITE).seen()) << "a wall";
    EXPECT_EQ(EPUCK_SEEN_OBJECT, Frame(640, 480, WHITE).paint(0.45, 0.4, 0.55, 0.6, RED).seen());
    EXPECT_EQ(EPUCK_SEEN_ROBOT, Frame(640, 480, WHITE).paint(0.4, 0.3, 0.6, 0.7, GREEN).seen());
    EXPECT_EQ(EPUCK_SEEN_OBJECT, Frame(640, 480, DARK).seen()) << "dark counts as an object";
    EXPECT_EQ(EPUCK_SEEN_OBJECT, Frame(640, 480, GREEN).paint(0.45, 0.4, 0.55, 0.6, RED).seen())
        << "red before green";
    EXPECT_EQ(EPUCK_SEEN_NOTHING, Frame(640, 480, WHITE).paint(0.0, 0.0, 0.3, 1.0, RED).seen())
        << "red outside the central window";
    EXPECT_EQ(EPUCK_SEEN_ROBOT, Frame(160, 120, WHITE).paint(0.4, 0.3, 0.6, 0.7, GREEN).seen())
        << "a smaller frame: the same share of it";
}

TEST(EpuckCamera, ThePlainJudgementIsTheProcessors) {
    // The world's frames (40 x 30, a colour per column) and others: the
    // function a plain loop calls says what the processor says.
    std::vector<Frame> frames = {Frame(40, 30, WHITE), Frame(40, 30, WHITE).paint(0.4, 0, 0.6, 1, RED),
                                 Frame(40, 30, WHITE).paint(0.3, 0, 0.7, 1, GREEN),
                                 Frame(40, 30, GREEN).paint(0.48, 0, 0.6, 1, RED),
                                 Frame(640, 480, WHITE).paint(0.45, 0.4, 0.55, 0.6, RED)};
    const uint8_t expected[] = {EPUCK_SEEN_NOTHING, EPUCK_SEEN_OBJECT, EPUCK_SEEN_ROBOT, EPUCK_SEEN_OBJECT,
                                EPUCK_SEEN_OBJECT};
    for (size_t k = 0; k < frames.size(); k++) {
        epuck_camera_frame f = {frames[k].pixels.data(), frames[k].width, frames[k].height, 0};
        epuck_seen seen = EPUCK_SEEN_NOTHING;
        ASSERT_TRUE(epuck_classify_frame(&f, &seen)) << "frame " << k;
        EXPECT_EQ(expected[k], seen) << "frame " << k;
        EXPECT_EQ(expected[k], frames[k].seen()) << "frame " << k;
    }
    std::vector<uint16_t> tiny(10 * 10, WHITE);
    epuck_camera_frame small = {tiny.data(), 10, 10, 0};
    epuck_seen seen;
    EXPECT_FALSE(epuck_classify_frame(&small, &seen));
}

TEST(EpuckCamera, RefusesWhatIsNotAFrame) {
    sys_device dev{};
    uint8_t out = 0;
    epuck_camera_frame none = {nullptr, 640, 480, 0};
    EXPECT_EQ(0, epuck_camera_classifier(&dev, &none, sizeof none, &out, 1));
    std::vector<uint16_t> tiny(10 * 10, WHITE);
    epuck_camera_frame small = {tiny.data(), 10, 10, 0};
    EXPECT_EQ(0, epuck_camera_classifier(&dev, &small, sizeof small, &out, 1));
}

TEST_F(Epuck, AFrameBecomesTheSeenEvent) {
    boot_devices();
    Frame f = Frame(640, 480, WHITE).paint(0.45, 0.4, 0.55, 0.6, RED);
    epuck_camera_frame frame = {f.pixels.data(), f.width, f.height, 0};
    irq([&] { epuck_camera_arrived(&frame); });
    settle();
    EXPECT_EQ(EPUCK_SEEN_OBJECT, event_value<uint8_t>(EPUCK_EVENT_CAMERA));
}

}  // namespace
