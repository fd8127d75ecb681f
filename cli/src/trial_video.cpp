#include "trial_video.hpp"

#include <algorithm>

#include "number_text.hpp"

namespace fs = std::filesystem;

namespace openswarm {

bool TrialVideo::wanted(int trial) const {
    return on && (trials.empty() || std::find(trials.begin(), trials.end(), trial + 1) != trials.end());
}

std::vector<std::string> TrialVideo::arguments(int trial) const {
    if (!wanted(trial)) return {};
    std::vector<std::string> args{"--video"};
    if (fps > 0) args.insert(args.end(), {"--video-fps", number_text(fps)});
    if (speed > 0) args.insert(args.end(), {"--video-speed", number_text(speed)});
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

void add_video_options(CLI::App *cmd, TrialVideo &video) {
    auto on = cmd->add_flag("--video", video.on,
                            "each trial also draws video.mp4 in its folder as it runs (needs ffmpeg); a trial done "
                            "before without it runs again");
    cmd->add_option("--video-fps", video.fps, "with --video: the video's frames a second, 1..100 (default 25)")
        ->type_name("F")->check(CLI::Range(1.0, 100.0))->needs(on);
    cmd->add_option("--video-speed", video.speed,
                    "with --video: simulated seconds a second of video, 0.01..10000 (default 1: real time)")
        ->type_name("X")->check(CLI::Range(0.01, 10000.0))->needs(on);
    cmd->add_option("--video-trials", video.trials,
                    "with --video: only these trials (counted from 1, as the progress lines name them; of every "
                    "point or controller), e.g. --video-trials 1,3")
        ->type_name("N,...")->delimiter(',')->check(CLI::Range(1, 10000))->needs(on);
}

}  // namespace openswarm
