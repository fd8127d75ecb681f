// The e-puck camera's noise (sim/src/world/epuck_camera_noise.c, the world
// file's "camera": "pixel_noise" and "misread_pct_per_m"; docs/world.md,
// "camera noise"): its statistics over many frames against the setting,
// each tolerance a few standard errors of its n; off, the frames of the
// model before the noise and no draw; each robot's stream its own.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <set>
#include <vector>

#include "world/epuck_camera_noise.h"
#include "world/epuck_sensors.h"
#include "world/world.h"
#include "world/world_random.h"

namespace {

constexpr int PIXELS = EPUCK_FRAME_WIDTH * EPUCK_FRAME_HEIGHT;
constexpr double Z = 5; // standard errors a statistic may stray (a false alarm once in ~3.5 million)

struct moments {
    double mean, sd;
    double sd_error; // a sample sd's standard error per sqrt(n): sqrt((m4 - sd^4) / 4) / sd
};

moments of(const std::vector<double> &v) {
    double sum = 0, squares = 0;
    for (double x : v) sum += x;
    double mean = sum / double(v.size());
    for (double x : v) squares += (x - mean) * (x - mean);
    return {mean, std::sqrt(squares / double(v.size())), 0};
}

unsigned red(uint16_t p) { return p >> 11; }
unsigned green(uint16_t p) { return (p >> 5) & 0x3Fu; }
unsigned blue(uint16_t p) { return p & 0x1Fu; }

// n pixels of one colour through the noise; each channel's values.
struct channels {
    std::vector<double> r, g, b;
};
channels noisy_pixels(uint16_t colour, double sd, int frames, uint64_t rng) {
    channels c;
    std::vector<uint16_t> frame(PIXELS);
    for (int f = 0; f < frames; f++) {
        frame.assign(PIXELS, colour);
        epuck_camera_pixel_noise(frame.data(), frame.size(), sd, &rng);
        for (uint16_t p : frame) {
            c.r.push_back(red(p));
            c.g.push_back(green(p));
            c.b.push_back(blue(p));
        }
    }
    return c;
}

// The law of a channel at value through the noise: a normal draw of sd
// rounded to whole counts, a result past 0 or top kept at it; summed over
// the counts it can end on.
moments law(unsigned value, double sd, unsigned top) {
    auto below = [sd](double counts) { return 0.5 * std::erfc(-counts / sd / std::sqrt(2)); };
    std::vector<double> p(top + 1);
    double mean = 0;
    for (unsigned c = 0; c <= top; c++) {
        p[c] = (c == top ? 1 : below(c + 0.5 - value)) - (c == 0 ? 0 : below(c - 0.5 - value));
        mean += p[c] * c;
    }
    double m2 = 0, m4 = 0;
    for (unsigned c = 0; c <= top; c++) {
        double d = c - mean;
        m2 += p[c] * d * d;
        m4 += p[c] * d * d * d * d;
    }
    return {mean, std::sqrt(m2), std::sqrt((m4 - m2 * m2) / 4) / std::sqrt(m2)};
}

// A channel's samples against its law: the mean and the sd each within Z
// of their standard errors for n samples.
void expect_channel(const std::vector<double> &v, unsigned value, double sd, unsigned top, const char *name) {
    moments m = of(v), expected = law(value, sd, top);
    double n = double(v.size());
    EXPECT_NEAR(m.mean, expected.mean, Z * expected.sd / std::sqrt(n)) << name << " channel's mean, sd " << sd;
    EXPECT_NEAR(m.sd, expected.sd, Z * expected.sd_error / std::sqrt(n)) << name << " channel's sd, sd " << sd;
    for (double x : v) ASSERT_LE(x, top) << name;
}

TEST(CameraPixelNoise, MeanAndSdMatchTheSetting) {
    const uint16_t mid = 16u << 11 | 32u << 5 | 16u;
    for (double sd : {0.5, 1.0, 3.0}) {
        channels c = noisy_pixels(mid, sd, 100, epuck_camera_stream(7, 0));
        expect_channel(c.r, 16, sd, 31, "red");
        expect_channel(c.g, 32, 2 * sd, 63, "green");
        expect_channel(c.b, 16, sd, 31, "blue");
        // Away from the channels' ends: the setting itself, give or take
        // the rounding to whole counts (Sheppard: + 1/12 in variance).
        EXPECT_NEAR(of(c.r).sd, std::sqrt(sd * sd + 1.0 / 12), 0.05 * sd) << "sd " << sd;
    }
}

// The world's colours sit at a channel's ends (white at the top of all
// three, red's green and blue at 0): a draw past an end stays at it.
TEST(CameraPixelNoise, KeptWithinEachChannel) {
    const double sd = 2;
    channels white = noisy_pixels(0xFFFF, sd, 100, epuck_camera_stream(7, 1));
    expect_channel(white.r, 31, sd, 31, "white's red");
    expect_channel(white.g, 63, 2 * sd, 63, "white's green");
    expect_channel(white.b, 31, sd, 31, "white's blue");
    channels red = noisy_pixels(0xF800, sd, 100, epuck_camera_stream(7, 2));
    expect_channel(red.g, 0, 2 * sd, 63, "red's green");
}

// One e-puck in the middle of a 4 x 4 m arena looking at an object
// gap_mm ahead of its centre (and a second robot behind it, which its
// camera does not see).
struct scene {
    std::vector<world_robot> robots;
    world_object object{};
    world_spec spec{};
    world *w = nullptr;
    scene(double gap_mm, double pixel_noise, double misread_pct_per_m) : robots(2) {
        robots[0].at = {2000, 2000};
        robots[1].at = {2000, 1000};
        for (auto &r : robots) r.firmware = -1;
        object = {{2000 + gap_mm + 200, 2000}, 200, 50, 0.5};
        spec.width_mm = spec.height_mm = 4000;
        spec.robots = robots.data();
        spec.n_robots = 2;
        spec.objects = &object;
        spec.n_objects = 1;
        spec.robot_kind = WORLD_ROBOT_EPUCK;
        spec.robot_radius_mm = 37;
        spec.camera_pixel_noise = pixel_noise;
        spec.camera_misread_pct_per_m = misread_pct_per_m;
        w = world_create(&spec);
    }
    ~scene() { world_destroy(w); }
};

TEST(CameraMisread, ShareOfAnObjectsColumnsShownAsWallGrowsWithDistance) {
    const double pct_per_m = 30;
    const int frames = 3000;
    const int centre[] = {EPUCK_FRAME_WIDTH / 2 - 1, EPUCK_FRAME_WIDTH / 2};
    for (double gap : {300.0, 1000.0}) {
        scene s(gap, 0, pct_per_m);
        uint64_t rng = epuck_camera_stream(3, 0);
        std::vector<uint16_t> frame(PIXELS);
        int walls = 0;
        for (int f = 0; f < frames; f++) {
            epuck_camera_render(s.w, 0, frame.data(), &rng);
            for (int col : centre) {
                uint16_t p = frame[col];
                ASSERT_TRUE(p == 0xF800 || p == 0xFFFF) << "column " << col << " shows " << p;
                walls += p == 0xFFFF;
                for (int row = 1; row < EPUCK_FRAME_HEIGHT; row++) ASSERT_EQ(frame[row * EPUCK_FRAME_WIDTH + col], p);
            }
        }
        double distance = world_ray(s.w, 0, 2000, 2000, 0, 4000).distance_mm;
        double p = pct_per_m / 100 * distance / 1000, n = 2.0 * frames;
        EXPECT_NEAR(walls / n, p, Z * std::sqrt(p * (1 - p) / n)) << "object " << distance << " mm away";
    }
}

TEST(CameraNoise, OffDrawsNothingAndShowsThePureColours) {
    scene s(300, 0, 0);
    uint64_t rng = epuck_camera_stream(3, 0), before = rng;
    std::vector<uint16_t> frame(PIXELS);
    epuck_camera_render(s.w, 0, frame.data(), &rng);
    EXPECT_EQ(rng, before) << "the camera's stream was drawn from with its noise off";
    int red = 0;
    for (uint16_t p : frame) {
        ASSERT_TRUE(p == 0xF800 || p == 0xFFFF) << "a pixel of " << p;
        red += p == 0xF800;
    }
    EXPECT_GT(red, 0) << "the object ahead does not show";
    EXPECT_LT(red, PIXELS) << "the walls beside the object do not show";
}

TEST(CameraNoise, EachRobotsStreamItsOwnAndTheSameForASeed) {
    EXPECT_EQ(epuck_camera_stream(5, 1), epuck_camera_stream(5, 1));
    EXPECT_NE(epuck_camera_stream(5, 1), epuck_camera_stream(6, 1));
    // No robot's stream is another's shifted by some draws (as robot i+4's
    // motion noise once replayed robot i's one step later): none of
    // robots 1..15's first draws is among robot 0's first 100 000.
    std::set<uint64_t> first;
    uint64_t r0 = epuck_camera_stream(5, 0);
    for (int k = 0; k < 100000; k++) first.insert(world_random_next(&r0));
    for (int robot = 1; robot < 16; robot++) {
        uint64_t r = epuck_camera_stream(5, robot);
        for (int k = 0; k < 1000; k++) ASSERT_EQ(first.count(world_random_next(&r)), 0u) << "robot " << robot;
    }
}

} // namespace
