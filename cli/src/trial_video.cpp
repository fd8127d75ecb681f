#include "trial_video.hpp"

#include <algorithm>
#include <cstdio>

namespace fs = std::filesystem;

namespace openswarm {

namespace {

std::string number(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", x);
    return text;
}

}  // namespace

bool TrialVideo::wanted(int trial) const {
    return on && (trials.empty() || std::find(trials.begin(), trials.end(), trial + 1) != trials.end());
}

std::vector<std::string> TrialVideo::arguments(int trial) const {
    if (!wanted(trial)) return {};
    std::vector<std::string> args{"--video"};
    if (fps > 0) args.insert(args.end(), {"--video-fps", number(fps)});
    if (speed > 0) args.insert(args.end(), {"--video-speed", number(speed)});
    return args;
}

std::string TrialVideo::request(int trial) const {
    std::string text;
    for (const std::string &a : arguments(trial)) text += (text.empty() ? "" : " ") + a;
    return text;
}

bool TrialVideo::missing(int trial, const fs::path &dir, const nlohmann::json &outcome) const {
    if (!wanted(trial)) return false;
    std::error_code ec;
    return outcome.value("video", "") != request(trial) || !fs::is_regular_file(dir / "video.mp4", ec);
}

}  // namespace openswarm
