// openswarm run: build the app, then run it in the simulator.
#include <csignal>
#include <filesystem>

#include "../app_config.hpp"
#include "../ports.hpp"
#include "../process.hpp"
#include "../qemu_run.hpp"
#include "../run_outputs.hpp"
#include "../suggest.hpp"
#include "build.hpp"
#include "commands.hpp"
#include "run_options.hpp"

namespace fs = std::filesystem;

namespace openswarm {

namespace {

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
    r.strict = o.strict;
    std::printf("Running %s in QEMU (netduinoplus2) for %g s\n", r.image.filename().c_str(),
                r.seconds);
    return run_in_qemu(r);
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
    bool qemu = false; // the world runs the app's e-puck2 image
    if (!o.world.empty()) {
        if (!world_file_usable(o)) return EXIT_USAGE;
        out_given = !o.out.empty();
        if (!out_given)
            o.out = (fs::path(o.dir) / "out" / fs::path(o.world).stem()).lexically_normal().string();
        const std::string fidelity = world_fidelity(o.world);
        o.native = o.native || fidelity == "native";
        qemu = !o.native && fidelity == "qemu";
    }
    if (o.native && !native_options_usable(o)) return EXIT_USAGE;
    auto parameters = parameter_options(o.parameters);
    if (!parameters) return exit_code;
    auto built = build_app(paths, o.dir, o.port, Progress::brief,
                           o.debug ? Variant::debug : o.native ? Variant::native : qemu ? Variant::qemu : Variant::release,
                           false, *parameters);
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
        if (!o.video_fps.empty()) argv.insert(argv.end(), {"--video-fps", o.video_fps});
        if (!o.video_speed.empty()) argv.insert(argv.end(), {"--video-speed", o.video_speed});
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
                    "with --world: write trajectories.csv, objects.csv, ir.csv (Kilobots), final.png and viewer.html "
                    "here (default: <app>/out/<world file's name>)")
        ->type_name("DIR")->needs(world);
    auto video = cmd->add_flag("--video", o->video, "with --world: also video.mp4 (needs ffmpeg)")->needs(world);
    cmd->add_option("--video-fps", o->video_fps, "with --video: the video's frames a second, 1..100 (default 25)")
        ->type_name("F")->needs(video);
    cmd->add_option("--video-speed", o->video_speed,
                    "with --video: simulated seconds a second of video, 0.01..10000 (default 1)")
        ->type_name("X")->needs(video);
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
                                 "--video", "--video-fps", "--video-speed", "--ids"})
            if (cmd->count(name) > 0) o->simavr_only.push_back(name);
        if (!o->simulator_options.empty()) o->simavr_only.push_back("options after --");
        exit_code = run_app(*o, paths);
    });
}

}  // namespace openswarm
