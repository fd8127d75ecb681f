// openswarm size: where the app's flash and RAM go - by owner (the kernel
// and port, the thread stacks, the events' data, the event queue, the app,
// the C runtime), each thread's stack and each event's data, and the
// OpenSwarm paper's equation (1) evaluated for this app.
#include <cstring>
#include <map>

#include "../app_config.hpp"
#include "../attribution.hpp"
#include "../footprint.hpp"
#include "../ports.hpp"
#include "../process.hpp"
#include "build.hpp"
#include "commands.hpp"

namespace fs = std::filesystem;

namespace openswarm {

namespace {

void print_owners(const BuildResult &built, const Attribution &a) {
    std::printf("\nImage %s: flash %u bytes, RAM %u bytes (plus the main stack).\n",
                built.image.string().c_str(), built.flash, built.ram);
    std::printf("Without link-time optimisation it would take %u and %u; by owner:\n",
                a.flash_total(), a.ram_total());
    std::printf("  %-24s %7s %7s\n", "", "flash", "RAM");
    std::map<std::string, bool> owners;
    for (const auto &[who, bytes] : a.flash) owners[who] = true;
    for (const auto &[who, bytes] : a.ram) owners[who] = true;
    for (const auto &[who, unused] : owners)
        std::printf("  %-24s %7u %7u\n", who.c_str(), a.flash_of(who), a.ram_of(who));
}

void print_line(const std::string &what, long bytes) {
    std::printf("  %-48s %7ld\n", what.c_str(), bytes);
}

void print_stacks(const Footprint &f) {
    std::printf(
        "\nThread stacks, as the pool carves them (requested + the port's %u + a %u-byte guard,\n"
        "in %u-byte blocks):\n",
        f.stack_extra, f.stack_guard, f.stack_block);
    for (const auto &t : f.threads)
        std::printf("  %-38s %6u -> %7u\n", t.name.c_str(), t.requested, t.carved);
    print_line("not listed: spare, or threads the code starts",
               (long)f.pool - (long)f.listed_stacks());
    print_line("the stack pool", f.pool);
}

void print_events(const Footprint &f) {
    std::printf("Events' data (d_i):\n");
    for (const auto &e : f.events) print_line(e.what, e.bytes);
    print_line("the kernel's and port's " + std::to_string(f.port_events) + " own events",
               f.port_event_bytes);
    print_line("not listed: spare",
               (long)f.event_data - (long)f.listed_data() - (long)f.port_event_bytes);
    print_line("the event data pool", f.event_data);
}

void print_equation(const Footprint &f) {
    const Equation &e = f.equation;
    std::printf("\nEquation (1): RAM = C + %u n + %u m + sum d_i + sum stacks = %u + %u*%u + %u*%u "
                "+ %u + %u = %u bytes\n",
                e.per_thread, e.per_event, e.fixed, e.per_thread, e.n, e.per_event, e.m, e.data,
                e.stacks, e.total());
    std::printf(
        "  (the paper's form; C, %u and %u measured on the minimal kernel, docs/benchmarks.md;\n"
        "  n: the threads listed above, m: openswarm.json's events)\n",
        e.per_thread, e.per_event);
    long gap = (long)f.reserved() - (long)e.total();
    std::printf("The build reserves %u bytes for the kernel (kernel and port %u + stacks %u + "
                "event data %u\n"
                "+ queue %u), %ld %s than equation (1):\n",
                f.reserved(), f.kernel, f.pool, f.event_data, f.queue, gap < 0 ? -gap : gap,
                gap < 0 ? "fewer" : "more");
    for (const auto &b : f.beyond) {
        std::string what = b.what;
        for (size_t at = what.find('\n'); at != std::string::npos; at = what.find('\n', at + 1))
            what.insert(at + 1, 11, ' '); // under the first line's text
        std::printf("  %7ld  %s\n", b.bytes, what.c_str());
    }
    for (const auto &w : f.warnings) std::printf("Warning: %s\n", w.c_str());
}

// "U/R,U/R,..." after "thread_stacks=" in the simulator's counters line:
// the live thread stacks' worst use and room, by address.
std::vector<std::pair<unsigned, unsigned>> thread_stacks_counted(const std::string &out) {
    std::vector<std::pair<unsigned, unsigned>> stacks;
    auto at = out.rfind("thread_stacks=");
    if (at == std::string::npos) return stacks;
    const char *p = out.c_str() + at + std::strlen("thread_stacks=");
    unsigned used, room;
    int n;
    while (std::sscanf(p, "%u/%u%n", &used, &room, &n) == 2) {
        stacks.emplace_back(used, room);
        p += n;
        if (*p++ != ',') break;
    }
    return stacks;
}

// Names for the stacks the simulator lists by address: openswarm.json's
// threads, when as many stacks live and each has the room its thread's
// carving gives (less the guard), in that order; else none.
std::vector<std::string> stack_names(const Footprint &f,
                                     const std::vector<std::pair<unsigned, unsigned>> &stacks) {
    if (stacks.size() != f.threads.size()) return {};
    std::vector<std::string> names;
    for (size_t i = 0; i < stacks.size(); i++) {
        if (stacks[i].second != f.threads[i].carved - f.stack_guard) return {};
        names.push_back(f.threads[i].name);
    }
    return names;
}

void print_thread_stacks(const Footprint &f, const std::string &out, const char *time) {
    auto stacks = thread_stacks_counted(out);
    if (stacks.empty()) return;
    auto names = stack_names(f, stacks);
    bool by_address = names.empty();
    for (size_t i = 0; by_address && i < stacks.size(); i++) names.push_back("stack " + std::to_string(i + 1));
    std::printf("Thread stacks: worst use in %s s in the simulator, of the room each has above its "
                "guard%s\n",
                time, by_address ? " (by address: the order the threads started in)" : "");
    for (size_t i = 0; i < stacks.size(); i++)
        std::printf("  %-38s %6u of %4u\n", names[i].c_str(), stacks[i].first, stacks[i].second);
    for (size_t i = 0; i < stacks.size(); i++)
        if (stacks[i].first > stacks[i].second)
            std::printf("Warning: %s overflowed its stack in the simulator: give it a larger "
                        "\"stack\" in openswarm.json\n",
                        names[i].c_str());
}

// The main stack's and the threads' worst use, measured by running the
// image in the simulator (openswarm-sim --main-stack --counters) for
// seconds of simulated time: the deepest their stack pointers went.
void print_stack_use(const Paths &paths, const BuildResult &built, const Footprint &f, double seconds) {
    const PortInfo &info = port_info(built.port);
    if (info.runner != Runner::simavr || paths.simulator.empty()) return;
    std::string out;
    char time[32];
    std::snprintf(time, sizeof time, "%g", seconds);
    int status = capture_program_and_errors({paths.simulator.string(), "--quiet", "--main-stack",
                                             "--counters", "0", "--time", time, built.image.string()},
                                            out);
    unsigned used = 0, room = 0;
    auto at = out.find("main stack: worst use ");
    if (at == std::string::npos ||
        std::sscanf(out.c_str() + at, "main stack: worst use %u of %u", &used, &room) != 2) {
        std::printf("\nMain stack: not measured (the simulator said: %s)\n", out.c_str());
        return;
    }
    std::printf("\nMain stack (main, interrupts, event handlers): worst use %u of its %u bytes in "
                "%s s in the simulator%s\n",
                used, room, time,
                status == 0 ? "" : " (the run failed: `openswarm run` shows why)");
    if (used >= room)
        std::printf("Warning: it ran into the RAM below it: lower the threads' \"stack\" in "
                    "openswarm.json\n");
    print_thread_stacks(f, out, time);
}

int run_size(const std::string &dir, const Paths &paths, double seconds, const std::vector<std::string> &settings) {
    auto parameters = parameter_options(settings);
    if (!parameters) return exit_code;
    auto built = build_app(paths, dir, "", Progress::on_stdout, Variant::release, false, *parameters);
    if (!built) return exit_code;
    std::printf("Building once more without link-time optimisation, to attribute every byte\n");
    std::string why;
    auto attribution = attribute_app(paths, dir, built->name, built->port, built->parameters, why);
    if (!attribution) {
        report("cannot attribute the image's bytes: " + why);
        return EXIT_FAILED;
    }
    print_owners(*built, *attribution);
    AppConfig config = load_app_config(dir); // build_app has validated it
    config.port = built->port;
    Footprint f =
        footprint_of(config, *attribution, generated_dir(dir, built->port) / "openswarm_config.h");
    print_stacks(f);
    print_events(f);
    print_equation(f);
    print_stack_use(paths, *built, f, seconds);
    return EXIT_OK;
}

}  // namespace

void add_size_command(CLI::App &app, const Paths &paths) {
    auto dir = std::make_shared<std::string>(".");
    auto seconds = std::make_shared<double>(5.0);
    auto settings = std::make_shared<std::vector<std::string>>();
    CLI::App *cmd = app.add_subcommand("size", "Show where the app's flash and RAM go");
    cmd->add_option("-C,--directory", *dir, "the app's folder")->capture_default_str();
    cmd->add_option("-t,--time", *seconds,
                    "simulated seconds to run the app for to measure its stacks' worst use (Kilobot)")
        ->capture_default_str()
        ->check(finite_seconds("--time", 0.001, 3600, "5"));
    cmd->add_option("-D,--param", *settings,
                    "a value for a parameter openswarm.json declares (\"parameters\"): the size of the image "
                    "built with it (in a folder of its own, as build -D)")
        ->type_name("NAME=VALUE")
        ->allow_extra_args(false);
    cmd->callback([dir, seconds, settings, &paths] { exit_code = run_size(*dir, paths, *seconds, *settings); });
}

}  // namespace openswarm
