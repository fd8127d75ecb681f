// openswarm run: build the app, then run it in the simulator.
#include <algorithm>
#include <csignal>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "../app_config.hpp"
#include "../ports.hpp"
#include "../process.hpp"
#include "../qemu_run.hpp"
#include "../run_outputs.hpp"
#include "../suggest.hpp"
#include "build.hpp"
#include "commands.hpp"

namespace fs = std::filesystem;

namespace openswarm {

namespace {

struct RunOptions {
    std::string dir = ".";
    std::string port;
    std::string time = "10";
    bool time_given = false;
    int robots = 1;
    int distance = 50;
    std::string line;      // --line SPACING: robots on a line
    std::string positions; // --positions FILE: one "x y" per robot
    std::vector<std::string> parameters; // -D NAME=VALUE
    int ir_range = 0;      // 0: the simulator's default
    bool robots_given = false;
    int gdb = 0;
    bool debug = false; // the debug image (build --debug)
    bool timestamps = false; // console lines begin with their time
    std::string vcd;
    std::vector<std::string> ohc; // overhead-controller messages, MSG@SECONDS
    bool profile = false;
    bool ir_log = false;
    std::string clock_spread; // percent; empty: the simulator's default (none)
    std::string ir_loss;      // percent at the range's edge; empty: none
    std::vector<std::string> first; // firmware robots 0, 1, ... run instead of the app
    std::vector<std::string> simulator_options; // after --, passed as they are
    std::string world; // --world FILE, relative to where the tool was started
    std::string out;   // --out DIR; empty: <app dir>/out/<world file's stem>
    bool video = false;
    bool ids = false;
    bool trace = false; // with --world; without it the trace is always on
    bool native = false; // --native, or the world's "fidelity": "native"
    bool strict = false; // the simulator's warnings at the end fail the run
    std::vector<std::string> simavr_only; // such options given, for a port QEMU runs
};

// "2.5", "2.5s" or "20%" (suffix): the number, if it is one in [lo, hi].
std::optional<double> number_in(std::string text, char suffix, double lo, double hi) {
    if (!text.empty() && text.back() == suffix) text.pop_back();
    char *end = nullptr;
    double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(v) || v < lo || v > hi) return std::nullopt;
    return v;
}

// The options whose mistakes the simulator would catch only after the
// build: caught before it, as bad usage. False after reporting.
bool run_options_usable(const RunOptions &o) {
    auto time = number_in(o.time, 's', 0, 86400);
    if (!time || *time <= 0) {
        report("--time " + o.time + ": give the simulated time in seconds, more than 0 and at most "
               "86400 (e.g. 10 or 2.5s)");
        return false;
    }
    if (!o.clock_spread.empty() && !number_in(o.clock_spread, '%', 0, 5)) {
        report("--clock-spread " + o.clock_spread + ": give a percentage from 0 to 5 (e.g. 1)");
        return false;
    }
    if (!o.ir_loss.empty() && !number_in(o.ir_loss, '%', 0, 100)) {
        report("--ir-loss " + o.ir_loss + ": give a percentage from 0 to 100 (e.g. 20)");
        return false;
    }
    for (const auto &m : o.ohc) {
        auto at = m.rfind('@');
        if (at == std::string::npos || at == 0 || !number_in(m.substr(at + 1), 's', 0, 86400)) {
            report("--ohc " + m + ": give MESSAGE@SECONDS, e.g. --ohc sleep@2 or "
                   "--ohc calib-left:70@1");
            return false;
        }
    }
    return true;
}

// A port whose robots live in a world (epuck_world): a world file places
// them; the Kilobot simulator's own options do not apply. False after
// reporting.
bool world_options_usable(const RunOptions &o, const std::string &port) {
    if (o.world.empty()) {
        report("the " + port + " port's robots run in a world: give --world FILE, a world.json with "
               "\"robot\": \"epuck\" (docs/world.md; the object-clustering template's experiment "
               "makes them)");
        return false;
    }
    std::vector<std::string> refused;
    for (const auto &name : o.simavr_only)
        if (name != "--world" && name != "--out" && name != "--video" && name != "--ids" &&
            name != "--trace")
            refused.push_back(name);
    if (refused.empty()) return true;
    report(join(refused) + ": not for the " + port + " port, whose robots the world file places; "
           "those are for Kilobot apps (--port kilobot)");
    return false;
}

// A port QEMU runs: one robot, no world (yet), the console and the trace.
int run_app_in_qemu(const RunOptions &o, const Paths &paths, const std::string &port) {
    if (!o.simavr_only.empty()) {
        report(join(o.simavr_only) + ": not for the " + port +
               " port, which runs one robot in QEMU; those are openswarm-sim's, for Kilobot "
               "apps (--port kilobot)");
        return EXIT_USAGE;
    }
    double seconds = *number_in(o.time, 's', 0, 86400);
    auto parameters = parameter_options(o.parameters);
    if (!parameters) return exit_code;
    auto built = build_app(paths, o.dir, o.port, Progress::brief,
                           o.debug ? Variant::debug : Variant::release, false, *parameters);
    if (!built) return exit_code;
    QemuRun r;
    r.image = built->image;
    r.seconds = seconds;
    r.gdb_port = o.gdb;
    std::printf("Running %s in QEMU (netduinoplus2) for %g s\n", r.image.filename().c_str(),
                r.seconds);
    return run_in_qemu(r);
}

// The world files an app ships (<dir>/worlds/*.json), to suggest when the
// one asked for is not there.
std::vector<std::string> app_worlds(const fs::path &dir) {
    std::vector<std::string> found;
    std::error_code ec;
    for (const auto &entry : fs::directory_iterator(dir / "worlds", ec))
        if (entry.path().extension() == ".json") found.push_back(entry.path().string());
    std::sort(found.begin(), found.end());
    return found;
}

// How long the world runs, for the first line: its duration_s, or the
// simulator's default. The simulator checks the file and reports its
// mistakes; here an unreadable file just says less.
std::string world_duration(const std::string &path) {
    try {
        std::ifstream in(path);
        auto world = nlohmann::json::parse(in);
        auto d = world.find("duration_s");
        if (d == world.end()) return "for 10 s (the world gives no duration_s)";
        if (d->is_number()) {
            std::ostringstream text;
            text << "for " << d->get<double>() << " s (its duration_s)";
            return text.str();
        }
    } catch (const std::exception &) {
    }
    return "for its duration_s";
}

// The world's "fidelity": "native" asks for the native mode (the
// simulator checks the file; an unreadable one says exact here).
bool world_wants_native(const std::string &path) {
    try {
        std::ifstream in(path);
        auto world = nlohmann::json::parse(in);
        auto f = world.find("fidelity");
        return f != world.end() && f->is_string() && f->get<std::string>() == "native";
    } catch (const std::exception &) {
        return false;
    }
}

// The options that look inside the simulated MCU, which the native mode
// does not simulate. False after reporting.
bool native_options_usable(const RunOptions &o) {
    std::vector<std::string> refused;
    if (o.gdb != 0) refused.push_back("--gdb");
    if (o.debug) refused.push_back("--debug");
    if (!o.vcd.empty()) refused.push_back("--vcd");
    if (!o.ohc.empty()) refused.push_back("--ohc");
    if (o.profile) refused.push_back("--profile");
    if (o.ir_log) refused.push_back("--ir-log");
    if (!o.first.empty()) refused.push_back("--first");
    if (o.trace) refused.push_back("--trace");
    if (refused.empty()) return true;
    report(join(refused) + ": the native mode runs the app on the host, with no simulated MCU to look "
           "into; run it in the exact mode (without --native, or \"fidelity\": \"exact\")");
    return false;
}

// A --world that names no file: say which file, where it was looked for,
// and what to give instead. False after reporting.
bool world_file_usable(const RunOptions &o) {
    std::error_code ec;
    if (fs::is_regular_file(o.world, ec)) return true;
    std::string message = "--world " + o.world + ": ";
    if (fs::exists(o.world, ec)) {
        message += "not a file; give a world.json (docs/world.md describes them)";
    } else {
        message += "no such file (looked for " +
                   fs::absolute(o.world).lexically_normal().string() + ")";
        if (o.dir != ".") message += "; the path is from the current folder, not from -C " + o.dir;
    }
    auto worlds = app_worlds(o.dir);
    if (!worlds.empty()) message += "; the app has: " + join(worlds);
    else message += "; write one as docs/world.md describes, or start from the disperse "
                    "template's worlds/packed.json";
    report(message);
    return false;
}

// The run's folder, with a copy of the world it ran in (world.json) for the
// metrics that need the arena or the lights; false after saying why not.
bool keep_world_beside_run(const std::string &world_path, const std::string &out) {
    std::error_code ec, same;
    fs::path copy = fs::path(out) / "world.json";
    if (fs::exists(copy, same) && fs::equivalent(world_path, copy, same)) return true;
    fs::create_directories(out, ec);
    if (!ec) fs::copy_file(world_path, copy, fs::copy_options::overwrite_existing, ec);
    if (!ec) return true;
    report("cannot keep the world in " + copy.string() + ": " + ec.message() +
           "; choose another --out folder or fix its permissions");
    return false;
}

int run_app(RunOptions o, const Paths &paths) {
    if (!run_options_usable(o)) return EXIT_USAGE;
    std::string port = port_given_or_app(o.port, o.dir);
    if (port == "epuck2" && !o.world.empty()) {
        // QEMU runs one robot and no world: an e-puck2 app's e-pucks in a
        // world are its sources built for the world simulator.
        std::printf("--world: the e-puck2 app runs in the world as --port epuck_world (docs/epuck.md)\n");
        o.port = port = "epuck_world";
    }
    if (is_port(port) && refuse_unrunnable(port, "run")) return EXIT_FAILED;
    if (is_port(port) && port_info(port).runner == Runner::qemu) return run_app_in_qemu(o, paths, port);
    if (is_port(port) && port_info(port).runner == Runner::world && !world_options_usable(o, port))
        return EXIT_USAGE;
    bool out_given = false;
    if (!o.world.empty()) {
        if (!world_file_usable(o)) return EXIT_USAGE;
        out_given = !o.out.empty();
        if (!out_given)
            o.out = (fs::path(o.dir) / "out" / fs::path(o.world).stem()).lexically_normal().string();
        o.native = o.native || world_wants_native(o.world);
    }
    if (o.native && !native_options_usable(o)) return EXIT_USAGE;
    auto parameters = parameter_options(o.parameters);
    if (!parameters) return exit_code;
    auto built = build_app(paths, o.dir, o.port, Progress::brief,
                           o.debug ? Variant::debug : o.native ? Variant::native : Variant::release, false, *parameters);
    if (!built) return exit_code;
    if (std::string why = simulator_problem(paths); !why.empty()) {
        report(why);
        return EXIT_FAILED;
    }
    const bool world = !o.world.empty();
    // Resolved now, from the folder the user typed it in, whatever folder
    // the simulator is later run from.
    const std::string world_path =
        world ? fs::absolute(o.world).lexically_normal().string() : std::string();
    std::string seconds = o.time;
    if (!seconds.empty() && seconds.back() == 's') seconds.pop_back();
    std::vector<std::string> argv = {paths.simulator.string()};
    // Without --world one robot's LED and motors are the whole show; in a
    // world, ten robots' changes would bury the status line and summary.
    if (!o.native && (!world || o.trace)) argv.push_back("--trace");
    // In a world, its duration_s applies unless --time was given.
    if (!world || o.time_given) argv.insert(argv.end(), {"--time", seconds});
    if (world) {
        if (!keep_last_run(o.out, out_given, world_path)) return EXIT_FAILED;
        argv.insert(argv.end(), {"--world", world_path, "--out", o.out});
        if (o.video) argv.push_back("--video");
        if (o.ids) argv.push_back("--ids");
        // A Kilobot's console lines (its `metric NAME VALUE` reports) and the
        // world beside the trajectories: `openswarm metrics OUT` needs no more.
        if (!(is_port(port) && port_info(port).runner == Runner::world)) {
            if (!keep_world_beside_run(world_path, o.out)) return EXIT_FAILED;
            argv.insert(argv.end(), {"--console-csv", (fs::path(o.out) / "console.csv").string()});
        }
    } else {
        // With --positions the file's line count is the number of robots; with
        // --first, the app runs on one robot after them unless told otherwise.
        int robots = o.robots_given || o.first.empty() ? o.robots : (int)o.first.size() + 1;
        if (o.positions.empty() || o.robots_given)
            argv.insert(argv.end(), {"--robots", std::to_string(robots)});
        if (!o.line.empty()) argv.insert(argv.end(), {"--line", o.line});
        else if (!o.positions.empty()) argv.insert(argv.end(), {"--positions", o.positions});
        else argv.insert(argv.end(), {"--distance", std::to_string(o.distance)});
    }
    if (o.ir_range != 0) argv.insert(argv.end(), {"--ir-range", std::to_string(o.ir_range)});
    if (o.gdb != 0) argv.insert(argv.end(), {"--gdb", std::to_string(o.gdb)});
    if (!o.vcd.empty()) argv.insert(argv.end(), {"--vcd", o.vcd});
    for (const auto &message : o.ohc) argv.insert(argv.end(), {"--ohc", message});
    if (o.profile) argv.push_back("--profile");
    if (o.strict) argv.push_back("--strict");
    if (o.timestamps) argv.push_back("--timestamps");
    if (o.ir_log) argv.push_back("--ir-log");
    if (!o.clock_spread.empty()) argv.insert(argv.end(), {"--clock-spread", o.clock_spread});
    if (!o.ir_loss.empty()) argv.insert(argv.end(), {"--ir-loss", o.ir_loss});
    argv.insert(argv.end(), o.simulator_options.begin(), o.simulator_options.end());
    argv.insert(argv.end(), o.first.begin(), o.first.end());
    argv.push_back(built->image.string());
    const std::string image = built->image.filename().string();
    if (!world)
        std::printf("Running %s in the simulator for %s s\n", image.c_str(), seconds.c_str());
    else if (o.time_given)
        std::printf("Running %s in the world %s for %s s\n", image.c_str(), o.world.c_str(),
                    seconds.c_str());
    else
        std::printf("Running %s in the world %s %s\n", image.c_str(), o.world.c_str(),
                    world_duration(world_path).c_str());
    std::fflush(stdout); // before the simulator's output, which goes straight to ours
    pass_interrupts_on(); // Ctrl-C or SIGTERM: the simulator writes the run so far
    int status = run_program(argv);
    if (interrupted_status(status)) {
        report(std::string("interrupted by ") + (status == 128 + SIGINT ? "SIGINT" : "SIGTERM") +
               " at the simulated time the simulator names above; " +
               (world ? "outputs written to " + o.out + " (open " + (fs::path(o.out) / "viewer.html").string() + ")"
                      : std::string("the run's output above ends there")) +
               "; run the same command again for the whole run");
        return status; // 130 or 143, as the shell reports a program it stopped
    }
    if (status != 0) {
        report(simulator_failure(status));
        // 2: it refused its input (a world file's mistake, ...): bad input,
        // the tool's own status 2, as docs/world.md says.
        return status == 2 ? EXIT_USAGE : EXIT_FAILED;
    }
    if (world) {
        fs::path out(o.out);
        std::printf("Open %s in a browser, or look at %s\n", (out / "viewer.html").string().c_str(),
                    (out / "final.png").string().c_str());
    }
    return EXIT_OK;
}

}  // namespace

void add_run_command(CLI::App &app, const Paths &paths) {
    auto o = std::make_shared<RunOptions>();
    CLI::App *cmd = app.add_subcommand("run", "Build the app and run it in the simulator");
    auto time = cmd->add_option("-t,--time", o->time,
                                "simulated time, seconds (e.g. 10 or 2.5s; with --world, default: the "
                                "world's duration_s)")
                    ->capture_default_str();
    auto robots = cmd->add_option("-n,--robots", o->robots, "robots running the app together")
        ->check(CLI::Range(1, 10000))->capture_default_str();
    auto distance =
        cmd->add_option("-d,--distance", o->distance, "millimetres between every two robots")
            ->check(CLI::Range(10, 1000))->capture_default_str();
    auto line =
        cmd->add_option("--line", o->line, "place the robots on a line, SPACING millimetres apart")
            ->type_name("SPACING")->excludes(distance);
    auto positions = cmd->add_option("--positions", o->positions,
                    "place the robots where FILE says: one \"x y\" line (millimetres) per robot")
        ->type_name("FILE")->excludes(distance)->excludes(line);
    auto world =
        cmd->add_option("--world", o->world,
                        "robots move in the world FILE describes (docs/world.md), which places "
                        "them; FILE is from the current folder, not from -C: "
                        "-C demo --world demo/worlds/packed.json")
            ->type_name("FILE")
            ->excludes(robots)->excludes(distance)->excludes(line)->excludes(positions);
    cmd->add_option("--out", o->out,
                    "with --world: write trajectories.csv, objects.csv, final.png and viewer.html "
                    "here (default: <app>/out/<world file's name>)")
        ->type_name("DIR")->needs(world);
    cmd->add_flag("--video", o->video, "with --world: also video.mp4 (needs ffmpeg)")->needs(world);
    cmd->add_flag("--ids", o->ids, "with --world: number the robots in final.png and the video")->needs(world);
    cmd->add_flag("--trace", o->trace,
                  "print every robot's LED and motor changes (without --world, always)");
    cmd->add_option("--ir-range", o->ir_range,
                    "millimetres a robot's IR reaches (simulator default 100)")
        ->check(CLI::Range(10, 1000));
    cmd->add_option("--gdb", o->gdb,
                    "wait for the debugger on this TCP port (avr-gdb; gdb-multiarch for epuck2)")
        ->check(CLI::Range(1, 65535));
    cmd->add_flag("--debug", o->debug,
                  "build and run the debug image (-Og, no link-time optimisation): with --gdb, "
                  "breakpoints on lines and every variable");
    cmd->add_option("--vcd", o->vcd, "record pins and motors into this GTKWave file");
    cmd->add_option("--ohc", o->ohc,
                    "the overhead controller sends MSG at SECONDS (run, sleep, reset, boot, "
                    "calib-left:70, ...; repeatable)")
        ->type_name("MSG@SECONDS");
    cmd->add_flag("--native", o->native,
                  "build the app for the host and run it in the native mode: thousands of robots, "
                  "timing charged per basic block rather than cycle-exact (docs/world.md, \"Native "
                  "mode\"; a world's \"fidelity\": \"native\" asks for it too)");
    cmd->add_flag("--profile", o->profile, "print where the CPU cycles went, by function");
    cmd->add_flag("--strict", o->strict,
                  "the warnings at the end of the run (a refused subscription or registration, a "
                  "lost event, printing from an interrupt) fail it, exit 1");
    cmd->add_flag("--timestamps", o->timestamps,
                  "begin every console line with its simulated time, as the trace's lines");
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
        ->allow_extra_args(false) // one file per --first: what follows is not its
        ->check(CLI::ExistingFile);
    cmd->add_option("simulator-options", o->simulator_options,
                    "after --: more openswarm-sim options, passed as they are (openswarm-sim --help), "
                    "e.g. -- --light 500 --uid 7")
        ->type_name("");
    cmd->add_option("-p,--port", o->port, "robot to build for (default: the app's port)");
    cmd->add_option("-D,--param", o->parameters,
                    "a value for a parameter openswarm.json declares (\"parameters\"), built "
                    "in a folder of its own")
        ->type_name("NAME=VALUE")
        ->allow_extra_args(false);
    cmd->add_option("-C,--directory", o->dir, "the app's folder")->capture_default_str();
    cmd->callback([o, robots, time, cmd, &paths] {
        o->robots_given = robots->count() > 0;
        o->time_given = time->count() > 0;
        o->simavr_only.clear();
        for (const char *name : {"--robots", "--distance", "--line", "--positions", "--world",
                                 "--ir-range", "--vcd", "--ohc", "--profile", "--ir-log", "--timestamps",
                                 "--clock-spread", "--ir-loss", "--first", "--trace", "--out",
                                 "--video", "--ids"})
            if (cmd->count(name) > 0) o->simavr_only.push_back(name);
        if (!o->simulator_options.empty()) o->simavr_only.push_back("options after --");
        exit_code = run_app(*o, paths);
    });
}

}  // namespace openswarm
