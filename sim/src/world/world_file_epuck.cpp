/* Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: links libsimavr (see sim/COPYING). */
/* The e-puck's sensing and noise in a world file: "camera" (how often a
 * frame comes and how late, how wide it sees and how far) and "noise" (the wheels' speed error). Both
 * are what the case study's sensitivity study sweeps (docs/case-study.md). */
#include <string>

#include "world/world_file_reader.hpp"

namespace world_file {

namespace {

const std::string camera_example =
    "\"camera\": {\"frames_per_s\": 4, \"lag_ms\": 0, \"fov_deg\": 56, \"range_mm\": 1500, \"pixel_noise\": 0, "
    "\"misread_pct_per_m\": 0}";
const std::string noise_example = "\"noise\": {\"wheels\": false}";

}  // namespace

/* A frame comes on a physics step (10 ms): the rate must divide 100. */
void Reader::camera(const Node &n, world_spec &w) {
    if (kind_ != WORLD_ROBOT_EPUCK)
        fail(n, "a Kilobot has no camera; \"camera\" is for e-puck worlds (\"robot\": \"epuck\"): remove it");
    object(n, {"frames_per_s", "lag_ms", "fov_deg", "range_mm", "pixel_noise", "misread_pct_per_m"}, camera_example);
    if (auto f = get(n, "frames_per_s")) {
        long fps = whole(*f, 1, 100, "frames a second", "\"frames_per_s\": 4");
        if (100 % fps != 0)
            fail(*f, "a frame comes on a 10 ms physics step, so the rate must divide 100 (1, 2, 4, 5, 10, 20, 25, "
                     "50 or 100 frames a second), found " + std::to_string(fps) + "; e.g. \"frames_per_s\": " +
                     std::to_string(fps < 5 ? 4 : fps < 10 ? 5 : fps < 20 ? 10 : fps < 25 ? 20 : fps < 50 ? 25 : 50));
        w.camera_period_ms = (int)(1000 / fps);
    }
    if (auto l = get(n, "lag_ms")) {
        long lag = whole(*l, 0, WORLD_CAMERA_MAX_LAG_MS, "ms from a frame's taking to its delivery", "\"lag_ms\": 250");
        if (lag % 10 != 0)
            fail(*l, "a frame is delivered on a 10 ms physics step, so the lag is a multiple of 10 ms, found " +
                         std::to_string(lag) + "; e.g. \"lag_ms\": " + std::to_string(lag / 10 * 10));
        w.camera_lag_ms = (int)lag;
    }
    if (auto f = get(n, "fov_deg"))
        w.camera_fov_deg = number(*f, 5, 180, false, "the camera's horizontal field of view in degrees", "\"fov_deg\": 56");
    if (auto r = get(n, "range_mm"))
        w.camera_range_mm = number(*r, 10, 100000, false,
                                   "mm within which the camera tells a robot or an object from the wall behind",
                                   "\"range_mm\": 1500");
    camera_noise(n, w);
}

/* The camera's noise, off unless given: no measured figure was found
 * (docs/world.md, "camera noise"), so these are for sensitivity studies. */
void Reader::camera_noise(const Node &n, world_spec &w) {
    if (auto s = get(n, "pixel_noise"))
        w.camera_pixel_noise = number(*s, 0, WORLD_CAMERA_MAX_PIXEL_NOISE, false,
                                      "each colour channel's noise, its standard deviation in 5-bit counts (green, "
                                      "6 bits, twice as many of its own)",
                                      "\"pixel_noise\": 2");
    if (auto p = get(n, "misread_pct_per_m"))
        w.camera_misread_pct_per_m = number(*p, 0, WORLD_CAMERA_MAX_MISREAD_PCT_PER_M, false,
                                            "percent chance per metre of distance that a robot's or an object's "
                                            "column shows the wall behind it",
                                            "\"misread_pct_per_m\": 20");
}

void Reader::noise(const Node &n, world_spec &w) {
    object(n, {"wheels", "wheels_pct"}, noise_example);
    auto on = get(n, "wheels");
    auto pct = get(n, "wheels_pct");
    if (on && pct)
        fail(*pct, "\"wheels\" and \"wheels_pct\" both say how the wheels err: give one (\"wheels_pct\": 0 turns "
                   "the noise off as \"wheels\": false does)");
    if (on) {
        if (!on.value()->is_boolean())
            fail(*on, "expected true (an e-puck's wheels err as the robot's do, docs/world.md) or false (they turn "
                      "exactly as commanded), found " + found(**on) + "; e.g. \"wheels\": false");
        w.wheel_noise_off = !on.value()->get<bool>();
    }
    if (pct) {
        w.wheel_noise_pct = number(*pct, 0, 50, false, "percent each wheel's speed errs by, +- (uniform, each step)",
                                   "\"wheels_pct\": 5");
        w.wheel_noise_off = w.wheel_noise_pct == 0;
    }
}

}  // namespace world_file
