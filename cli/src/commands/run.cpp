// openswarm run: build the app, then run it in the simulator.
#include "../process.hpp"
#include "build.hpp"
#include "commands.hpp"

namespace openswarm {

namespace {

struct RunOptions {
    std::string dir = ".";
    std::string port;
    std::string time = "10";
    int robots = 1;
    int distance = 50;
    std::string line;      // --line SPACING: robots on a line
    std::string positions; // --positions FILE: one "x y" per robot
    int ir_range = 0;      // 0: the simulator's default
    bool robots_given = false;
    int gdb = 0;
    std::string vcd;
    std::vector<std::string> ohc; // overhead-controller messages, MSG@SECONDS
    bool profile = false;
    bool ir_log = false;
    std::string clock_spread; // percent; empty: the simulator's default (none)
    std::string ir_loss;      // percent at the range's edge; empty: none
    std::vector<std::string> first; // firmware robots 0, 1, ... run instead of the app
    std::vector<std::string> simulator_options; // after --, passed as they are
};

int run_app(const RunOptions &o, const Paths &paths) {
    auto built = build_app(paths, o.dir, o.port);
    if (!built) return exit_code;
    if (paths.simulator.empty()) {
        report("openswarm-sim was not found next to this tool; build it with "
               "`cmake --build <openswarm>/build --target openswarm-sim`");
        return EXIT_FAILED;
    }
    std::string seconds = o.time;
    if (!seconds.empty() && seconds.back() == 's') seconds.pop_back();
    std::vector<std::string> argv = {paths.simulator.string(), "--trace", "--time", seconds};
    // With --positions the file's line count is the number of robots; with
    // --first, the app runs on one robot after them unless told otherwise.
    int robots = o.robots_given || o.first.empty() ? o.robots : (int)o.first.size() + 1;
    if (o.positions.empty() || o.robots_given)
        argv.insert(argv.end(), {"--robots", std::to_string(robots)});
    if (!o.line.empty()) argv.insert(argv.end(), {"--line", o.line});
    else if (!o.positions.empty()) argv.insert(argv.end(), {"--positions", o.positions});
    else argv.insert(argv.end(), {"--distance", std::to_string(o.distance)});
    if (o.ir_range != 0) argv.insert(argv.end(), {"--ir-range", std::to_string(o.ir_range)});
    if (o.gdb != 0) argv.insert(argv.end(), {"--gdb", std::to_string(o.gdb)});
    if (!o.vcd.empty()) argv.insert(argv.end(), {"--vcd", o.vcd});
    for (const auto &message : o.ohc) argv.insert(argv.end(), {"--ohc", message});
    if (o.profile) argv.push_back("--profile");
    if (o.ir_log) argv.push_back("--ir-log");
    if (!o.clock_spread.empty()) argv.insert(argv.end(), {"--clock-spread", o.clock_spread});
    if (!o.ir_loss.empty()) argv.insert(argv.end(), {"--ir-loss", o.ir_loss});
    argv.insert(argv.end(), o.simulator_options.begin(), o.simulator_options.end());
    argv.insert(argv.end(), o.first.begin(), o.first.end());
    argv.push_back(built->image.string());
    std::printf("Running %s in the simulator for %s s\n", built->image.filename().string().c_str(),
                seconds.c_str());
    int status = run_program(argv);
    return status == 0 ? EXIT_OK : EXIT_FAILED;
}

}  // namespace

void add_run_command(CLI::App &app, const Paths &paths) {
    auto o = std::make_shared<RunOptions>();
    CLI::App *cmd = app.add_subcommand("run", "Build the app and run it in the simulator");
    cmd->add_option("-t,--time", o->time, "simulated time, seconds (e.g. 10 or 2.5s)")->capture_default_str();
    auto robots = cmd->add_option("-n,--robots", o->robots, "robots running the app together")
        ->check(CLI::Range(1, 64))->capture_default_str();
    auto distance =
        cmd->add_option("-d,--distance", o->distance, "millimetres between every two robots")
            ->check(CLI::Range(10, 1000))->capture_default_str();
    auto line =
        cmd->add_option("--line", o->line, "place the robots on a line, SPACING millimetres apart")
            ->type_name("SPACING")->excludes(distance);
    cmd->add_option("--positions", o->positions,
                    "place the robots where FILE says: one \"x y\" line (millimetres) per robot")
        ->type_name("FILE")->excludes(distance)->excludes(line);
    cmd->add_option("--ir-range", o->ir_range,
                    "millimetres a robot's IR reaches (simulator default 100)")
        ->check(CLI::Range(10, 1000));
    cmd->add_option("--gdb", o->gdb, "wait for avr-gdb on this TCP port")->check(CLI::Range(1, 65535));
    cmd->add_option("--vcd", o->vcd, "record pins and motors into this GTKWave file");
    cmd->add_option("--ohc", o->ohc,
                    "the overhead controller sends MSG at SECONDS (run, sleep, reset, boot, "
                    "calib-left:70, ...; repeatable)")
        ->type_name("MSG@SECONDS");
    cmd->add_flag("--profile", o->profile, "print where the CPU cycles went, by function");
    cmd->add_flag("--ir-log", o->ir_log,
                  "print every frame the robots send, decoded by the Kilobot wire format");
    cmd->add_option("--clock-spread", o->clock_spread,
                    "the robots' clocks run fast or slow by up to PCT percent (0-5), as real ones")
        ->type_name("PCT");
    cmd->add_option("--ir-loss", o->ir_loss,
                    "lose PCT percent of the frames at the IR range's edge, fewer closer in")
        ->type_name("PCT");
    cmd->add_option("--first", o->first,
                    "robot 0 runs this firmware instead of the app (given twice: robots 0 and 1, "
                    "...); the app runs on the robots after them, e.g. a seed robot: "
                    "--first ../seed/build/kilobot/seed.elf")
        ->type_name("ELF")
        ->check(CLI::ExistingFile);
    cmd->add_option("simulator-options", o->simulator_options,
                    "after --: more openswarm-sim options, passed as they are (openswarm-sim --help), "
                    "e.g. -- --light 500 --uid 7")
        ->type_name("");
    cmd->add_option("-p,--port", o->port, "robot to build for (default: the app's port)");
    cmd->add_option("-C,--directory", o->dir, "the app's folder")->capture_default_str();
    cmd->callback([o, robots, &paths] {
        o->robots_given = robots->count() > 0;
        exit_code = run_app(*o, paths);
    });
}

}  // namespace openswarm
