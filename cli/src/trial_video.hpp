// `openswarm experiment --video`: a video of a trial, drawn by the
// simulator as the trial runs (video.mp4 in the trial's folder, at the
// video's own rate: docs/world.md, "Outputs"), for every trial or only
// those named. Sweeps and the clustering experiment alike.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

namespace openswarm {

struct TrialVideo {
    bool on = false;          // --video
    double fps = 0;           // --video-fps; 0: the simulator's default
    double speed = 0;         // --video-speed; 0: likewise
    std::vector<int> trials;  // --video-trials, counted from 1; empty: every trial

    // Whether trial t (from 0) is filmed.
    bool wanted(int trial) const;
    // The simulator's options for trial t: none when it is not filmed.
    std::vector<std::string> arguments(int trial) const;
    // What trial t's outcome.json records of its video (its options; ""
    // for none), so that a video asked for later, or at another rate,
    // runs the trial again.
    std::string request(int trial) const;
    // Whether trial t, done before with `outcome`, still lacks the video
    // asked for now.
    bool missing(int trial, const std::filesystem::path &dir, const nlohmann::json &outcome) const;
};

// --video, --video-fps, --video-speed and --video-trials on a command.
void add_video_options(CLI::App *cmd, TrialVideo &video);

}  // namespace openswarm
