// openswarm test: build the app, run each of its tests in the simulator and
// compare what the robots did with what the test expects.
//
// A test is a file tests/NAME.trace in the app: a first line
// "# run: <simulator options>" (e.g. --time 1.2 --robots 2), then one
// expected change a line, "time_s,device,a,b,c" (robot 0) or
// "time_s,robot,device,a,b,c"; times may be 5 ms off. Each robot's changes
// are compared in order. Lines "> TEXT" are console lines the run must
// print, in that order (others may come between). `test --record NAME`
// writes such a file from a run, in the Kilobot simulator or in QEMU.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "../app_config.hpp"
#include "../json_checks.hpp"
#include "../ports.hpp"
#include "../process.hpp"
#include "../qemu_run.hpp"
#include "../regular_file.hpp"
#include "../suggest.hpp"
#include "build.hpp"
#include "commands.hpp"

namespace fs = std::filesystem;

namespace openswarm {

namespace {

const double tolerance_s = 0.005;

struct Change {
    double t;
    int robot;
    std::string device;
    int a, b, c;
    int line; // in the expectation, 0 for the simulator's
};

std::vector<std::string> split(const std::string &s, char sep) {
    std::vector<std::string> parts;
    std::string part;
    std::istringstream in(s);
    while (std::getline(in, part, sep)) parts.push_back(part);
    return parts;
}

struct ConsoleLine {
    std::string text;
    int line; // in the expectation
};

struct Expectation {
    std::vector<std::string> options;
    std::vector<Change> changes;
    std::vector<ConsoleLine> console;
};

// The whole of text is a finite number (std::stod alone took "nan" and
// the 3 of "3abc").
bool whole_real(const std::string &text, double &out) {
    char *end = nullptr;
    errno = 0;
    out = std::strtod(text.c_str(), &end);
    return !text.empty() && *end == '\0' && errno == 0 && std::isfinite(out);
}

bool whole_long(const std::string &text, long &out) {
    char *end = nullptr;
    errno = 0;
    out = std::strtol(text.c_str(), &end, 10);
    return !text.empty() && *end == '\0' && errno == 0 && out >= -32768 && out <= 65535;
}

Expectation read_expectation(const fs::path &file) {
    Expectation e;
    std::string kind = not_a_regular_file(file);
    if (!kind.empty())
        throw std::runtime_error(file.string() + ": " + kind + ", not a regular file; a test is a text file "
                                 "(`openswarm test --record NAME` writes one): move it out of tests/");
    std::ifstream in(file);
    std::string line;
    for (int n = 1; std::getline(in, line); n++) {
        if (line.rfind("# run:", 0) == 0) {
            std::istringstream words(line.substr(6));
            std::string w;
            while (words >> w) e.options.push_back(w);
            continue;
        }
        if (line.rfind("> ", 0) == 0) {
            e.console.push_back({line.substr(2), n});
            continue;
        }
        if (line.empty() || line[0] == '#') continue;
        auto f = split(line, ',');
        if (f.size() == 5) f.insert(f.begin() + 1, "0");
        double t = 0;
        long robot = 0, a = 0, b = 0, c = 0;
        if (f.size() != 6 || !whole_real(f[0], t) || !whole_long(f[1], robot) || !whole_long(f[3], a) ||
            !whole_long(f[4], b) || !whole_long(f[5], c) || t < 0 || robot < 0 || robot > 65535)
            throw std::runtime_error(file.string() + ":" + std::to_string(n) + ": " + text_start(line, 60) +
                                     ": expected time_s,device,a,b,c or time_s,robot,device,a,b,c (a time in "
                                     "seconds, whole numbers), e.g. 0.252,led,0,3,0");
        e.changes.push_back({t, (int)robot, f[2], (int)a, (int)b, (int)c, n});
    }
    return e;
}

std::vector<Change> read_trace(const fs::path &csv) {
    std::vector<Change> out;
    std::ifstream in(csv);
    std::string line;
    std::getline(in, line); // header: time_s,cycle,robot,device,a,b,c
    while (std::getline(in, line)) {
        auto f = split(line, ',');
        if (f.size() == 7) out.push_back({std::stod(f[0]), std::stoi(f[2]), f[3], std::stoi(f[4]), std::stoi(f[5]), std::stoi(f[6]), 0});
    }
    return out;
}

std::string describe(const Change &c) {
    char text[96];
    std::snprintf(text, sizeof text, "robot %d %s %d %d %d at %.3f s", c.robot, c.device.c_str(), c.a, c.b, c.c, c.t);
    return text;
}

// Mismatches, one a line; empty if the trace is as expected.
std::vector<std::string> compare(const fs::path &file, const std::vector<Change> &want, const std::vector<Change> &got) {
    std::map<int, std::vector<Change>> want_by, got_by;
    for (const auto &c : want) want_by[c.robot].push_back(c);
    for (const auto &c : got) {
        got_by[c.robot].push_back(c);
        want_by[c.robot]; // every robot that did something is checked
    }
    std::vector<std::string> problems;
    for (const auto &[robot, expected] : want_by) {
        const auto &actual = got_by[robot];
        for (size_t i = expected.size(); i < actual.size(); i++)
            problems.push_back(file.string() + ": unexpected " + describe(actual[i]));
        for (size_t i = 0; i < expected.size(); i++) {
            const Change &w = expected[i];
            std::string where = file.string() + ":" + std::to_string(w.line) + ": expected " + describe(w);
            if (i >= actual.size()) {
                problems.push_back(where + ", nothing more happened");
                continue;
            }
            const Change &g = actual[i];
            if (g.device != w.device || g.a != w.a || g.b != w.b || g.c != w.c || std::abs(g.t - w.t) > tolerance_s)
                problems.push_back(where + ", got " + describe(g));
        }
    }
    return problems;
}

// The expected console lines, in order, among those printed.
std::vector<std::string> compare_console(const fs::path &file, const std::vector<ConsoleLine> &want,
                                         const std::vector<std::string> &got) {
    size_t at = 0;
    for (const auto &w : want) {
        while (at < got.size() && got[at] != w.text) at++;
        if (at == got.size())
            return {file.string() + ":" + std::to_string(w.line) + ": expected the console line '" +
                    w.text + "'" + (w.line == want.front().line ? "" : " after the ones before it") +
                    ", not printed"};
        at++;
    }
    return {};
}

// A run in the simulator or QEMU: its LED and motor changes, its console
// lines (the simulator's own lines left out); the failure if it failed.
struct TestRun {
    std::vector<Change> changes;
    std::vector<std::string> console;
    std::string failure;
};

// The simulator's warnings (what the firmware lost or refused) are shown
// even when the test passes; with --strict they fail it.
TestRun run_in_simulator(const std::string &name, const std::vector<std::string> &options,
                         const fs::path &image, const Paths &paths, bool strict) {
    fs::path csv = image.parent_path() / (name + ".trace.csv");
    std::vector<std::string> argv = {paths.simulator.string(), "--no-progress", "--trace-csv", csv.string()};
    if (strict) argv.push_back("--strict");
    argv.insert(argv.end(), options.begin(), options.end());
    argv.push_back(image.string());
    std::string output;
    TestRun run;
    int status = capture_program_and_errors(argv, output);
    std::istringstream lines(output);
    std::string simulator_said; // its own lines: shown when the run failed
    for (std::string line; std::getline(lines, line);) {
        if (line.rfind("openswarm-sim:", 0) != 0)
            run.console.push_back(line);
        else if (line.find(" warning: ") != std::string::npos && status == 0)
            std::fprintf(stderr, "%s\n", line.c_str());
        else
            simulator_said += line + "\n";
    }
    if (status != 0) {
        std::fprintf(stderr, "%s", simulator_said.c_str());
        run.failure = simulator_failure(status);
        return run;
    }
    run.changes = read_trace(csv);
    return run;
}

// A port QEMU runs takes one robot, and of the options only --time: what
// is wrong with them (empty if nothing), with the run's time set in r.
std::string qemu_options(const std::vector<std::string> &options, QemuRun &r) {
    for (size_t i = 0; i < options.size(); i++) {
        if (options[i] == "--time" && i + 1 < options.size()) {
            std::string t = options[++i];
            if (!t.empty() && t.back() == 's') t.pop_back();
            char *end = nullptr;
            r.seconds = std::strtod(t.c_str(), &end);
            if (*end != '\0' || !std::isfinite(r.seconds) || r.seconds <= 0 || r.seconds > 86400)
                return "--time " + options[i] + ": give seconds, more than 0 and at most 86400";
            continue;
        }
        return options[i] + ": QEMU runs one robot, and of the run options takes only --time";
    }
    return "";
}

// A run in QEMU with options qemu_options accepted: the board's records
// as changes of robot 0. Its warnings are shown as the simulator's are.
TestRun run_in_qemu(const std::vector<std::string> &options, const fs::path &image, bool strict) {
    QemuRun r;
    r.image = image;
    r.strict = strict;
    qemu_options(options, r);
    QemuOutcome outcome = run_qemu(r, [](const std::string &) {});
    show_warnings(outcome);
    TestRun run;
    run.failure = qemu_failure(r, outcome);
    if (!run.failure.empty()) return run;
    for (const auto &rec : outcome.records) {
        std::vector<int> v = rec.values; // a, b, c: fewer values are padded with 0
        v.resize(3, 0);
        run.changes.push_back({rec.t, 0, rec.name, v[0], v[1], v[2], 0});
    }
    run.console = outcome.console;
    return run;
}

// A run of the image where its port runs; options already checked.
TestRun run_on_port(const std::string &port, const std::string &name, const std::vector<std::string> &options,
                    const fs::path &image, const Paths &paths, bool strict) {
    if (port_info(port).runner == Runner::qemu) return run_in_qemu(options, image, strict);
    return run_in_simulator(name, options, image, paths, strict);
}

std::vector<std::string> run_and_compare(const std::string &port, const fs::path &file, const Expectation &e,
                                         const fs::path &image, const Paths &paths, bool strict) {
    if (port_info(port).runner == Runner::qemu) {
        QemuRun unused;
        std::string wrong = qemu_options(e.options, unused);
        if (!wrong.empty()) return {file.string() + ":1: " + wrong};
    }
    TestRun run = run_on_port(port, file.stem().string(), e.options, image, paths, strict);
    if (!run.failure.empty()) return {run.failure};
    auto problems = compare(file, e.changes, run.changes);
    for (auto &p : compare_console(file, e.console, run.console)) problems.push_back(p);
    return problems;
}

// The app's port runs nowhere here (reported); a missing or broken
// openswarm.json is build_app's to report.
bool runs_nowhere(const std::string &dir) {
    std::string port;
    try {
        port = load_app_config(dir).port;
    } catch (const std::exception &) {
        return false;
    }
    if (is_port(port) && port_info(port).runner == Runner::world) {
        report("`openswarm test` checks one robot's trace, and the " + port +
               " port's robots run only in a world: `openswarm run --world FILE`, or an "
               "experiment (`openswarm experiment FILE`)");
        return true;
    }
    return is_port(port) && refuse_unrunnable(port, "test");
}

struct TestOptions {
    std::string dir = ".";
    std::string record;               // a test to write from a run
    std::vector<std::string> options; // the run's, after -- (--record); else the tests to run
    std::vector<std::string> parameters; // -D NAME=VALUE
    bool force = false;
    bool strict = false; // the simulator's warnings fail the test
};

// tests/NAME.trace from a run with the options given: what the robots
// did and printed, to be checked from now on.
int record_test(const TestOptions &o, const Paths &paths) {
    if (!std::regex_match(o.record, std::regex("[A-Za-z0-9_-]+"))) {
        report("--record " + o.record + ": a test's name is letters, digits, - and _ (it names tests/NAME.trace)");
        return EXIT_USAGE;
    }
    fs::path file = fs::path(o.dir) / "tests" / (o.record + ".trace");
    if (fs::exists(file) && !o.force) {
        report(file.string() + " exists: pass --force to record it again");
        return EXIT_USAGE;
    }
    if (runs_nowhere(o.dir)) return EXIT_FAILED;
    auto parameters = parameter_options(o.parameters);
    if (!parameters) return exit_code;
    auto built = build_app(paths, o.dir, "", Progress::brief, Variant::release, false, *parameters);
    if (!built) return exit_code;
    std::vector<std::string> options = o.options.empty() ? std::vector<std::string>{"--time", "1"} : o.options;
    if (port_info(built->port).runner == Runner::qemu) {
        QemuRun unused;
        std::string wrong = qemu_options(options, unused);
        if (!wrong.empty()) {
            report("--record on the " + built->port + " port: " + wrong);
            return EXIT_USAGE;
        }
    }
    TestRun run = run_on_port(built->port, o.record, options, built->image, paths, o.strict);
    if (!run.failure.empty()) {
        report("the run failed, so nothing was recorded: " + run.failure);
        return EXIT_FAILED;
    }
    bool several = false;
    for (const auto &c : run.changes) several |= c.robot != 0;
    fs::create_directories(file.parent_path());
    std::ofstream out(file);
    out << "# run:";
    for (const auto &w : options) out << " " << w;
    out << "\n# Recorded by `openswarm test --record " << o.record
        << "`: what the robots did and printed; edit freely.\n";
    for (const auto &line : run.console) out << "> " << line << "\n";
    char row[128];
    for (const auto &c : run.changes) {
        if (several)
            std::snprintf(row, sizeof row, "%.3f,%d,%s,%d,%d,%d\n", c.t, c.robot, c.device.c_str(), c.a, c.b, c.c);
        else
            std::snprintf(row, sizeof row, "%.3f,%s,%d,%d,%d\n", c.t, c.device.c_str(), c.a, c.b, c.c);
        out << row;
    }
    if (!out) {
        report("cannot write " + file.string());
        return EXIT_FAILED;
    }
    std::printf("Recorded %s: %zu changes, %zu console lines; `openswarm test` checks them from now on\n",
                file.string().c_str(), run.changes.size(), run.console.size());
    return EXIT_OK;
}

// The tests named (all when none is), in files; false, reported, if a
// name is no test's.
bool select_tests(std::vector<fs::path> &files, const std::vector<std::string> &names, const fs::path &tests) {
    if (names.empty()) return true;
    std::vector<std::string> known;
    for (const auto &f : files) known.push_back(f.stem().string());
    std::vector<fs::path> chosen;
    for (const auto &name : names) {
        auto at = std::find(known.begin(), known.end(), name);
        if (at == known.end()) {
            report("no test '" + name + "' (" + (tests / (name + ".trace")).string() + ")" +
                   did_you_mean(name, known, '\'') + "; tests: " + join(known) +
                   " (`openswarm test --record " + name + "` writes one)");
            return false;
        }
        chosen.push_back(files[at - known.begin()]);
    }
    files = chosen;
    return true;
}

int run_tests(const std::string &dir, const std::vector<std::string> &names, const std::vector<std::string> &settings,
              bool strict, const Paths &paths) {
    fs::path tests = fs::path(dir) / "tests";
    std::vector<fs::path> files;
    if (fs::exists(tests))
        for (const auto &e : fs::directory_iterator(tests))
            if (e.path().extension() == ".trace") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    if (files.empty()) {
        report("no tests: add tests/NAME.trace files to " + fs::path(dir).string() +
               " (see `openswarm test --help`)");
        return EXIT_USAGE;
    }
    if (!select_tests(files, names, tests)) return EXIT_USAGE;
    // A test file that cannot be read is bad input, refused before the build.
    std::vector<Expectation> expected;
    try {
        for (const auto &file : files) expected.push_back(read_expectation(file));
    } catch (const std::runtime_error &ex) {
        report(std::string(ex.what()));
        return EXIT_USAGE;
    }
    if (runs_nowhere(dir)) return EXIT_FAILED;
    auto parameters = parameter_options(settings);
    if (!parameters) return exit_code;
    auto built = build_app(paths, dir, "", Progress::brief, Variant::release, false, *parameters);
    if (!built) return exit_code;
    int passed = 0, failed = 0;
    std::vector<std::pair<std::string, std::string>> rows;
    for (size_t i = 0; i < files.size(); i++) {
        const fs::path &file = files[i];
        const Expectation &e = expected[i];
        std::string name = file.stem().string();
        std::vector<std::string> problems;
        try {
            problems = run_and_compare(built->port, file, e, built->image, paths, strict);
        } catch (const std::exception &ex) {
            problems.push_back(ex.what());
        }
        for (const auto &p : problems) std::printf("%s\n", p.c_str());
        rows.emplace_back(name, problems.empty() ? "PASSED" : "FAILED");
        (problems.empty() ? passed : failed)++;
    }
    std::printf("\n%-24s %s\n", "Test", "Result");
    for (const auto &[name, result] : rows) std::printf("%-24s %s\n", name.c_str(), result.c_str());
    std::printf("%d passed, %d failed\n", passed, failed);
    return failed == 0 ? EXIT_OK : EXIT_FAILED;
}

}  // namespace

void add_test_command(CLI::App &app, const Paths &paths) {
    auto o = std::make_shared<TestOptions>();
    CLI::App *cmd = app.add_subcommand("test", "Run the app's tests (tests/*.trace, or those named) in the simulator");
    cmd->footer("A test is tests/NAME.trace: a line \"# run: <simulator options>\" (e.g. --time 1.2\n"
                "--robots 2), then one expected LED or motor change a line: time_s,device,a,b,c\n"
                "(robot 0) or time_s,robot,device,a,b,c. Times may be 5 ms off. Lines \"> TEXT\" are\n"
                "console lines the run must print, in order. `openswarm test --record NAME -- --time 2\n"
                "--robots 3` writes tests/NAME.trace from a run.");
    cmd->add_option("-C,--directory", o->dir, "the app's folder")->capture_default_str();
    cmd->add_option("--record", o->record,
                    "run once and write tests/NAME.trace from what the robots did and printed "
                    "(simulator options after --; default --time 1)")
        ->type_name("NAME");
    cmd->add_flag("-f,--force", o->force, "with --record: replace an existing test");
    cmd->add_option("-D,--param", o->parameters,
                    "a value for a parameter openswarm.json declares (\"parameters\"): the tests run (or "
                    "--record records) the image built with it, in a folder of its own as build -D")
        ->type_name("NAME=VALUE")
        ->allow_extra_args(false);
    cmd->add_flag("--strict", o->strict,
                  "the warnings at the end of a run (a refused subscription or registration, a lost "
                  "event, printing from an interrupt) fail the test");
    // One list for both: CLI11 gives the words after -- to the first
    // positional, so the names and --record's options cannot be two.
    cmd->add_option("names-or-options", o->options,
                    "the tests to run (NAME: tests/NAME.trace; all by default), or with --record, "
                    "after --, the recorded run's simulator options")
        ->type_name("NAME...");
    cmd->callback([o, &paths] {
        bool options_given = std::any_of(o->options.begin(), o->options.end(),
                                         [](const std::string &w) { return w.rfind('-', 0) == 0; });
        if (o->record.empty() && (options_given || o->force)) {
            report("options after -- and --force go with --record NAME");
            exit_code = EXIT_USAGE;
            return;
        }
        exit_code = o->record.empty() ? run_tests(o->dir, o->options, o->parameters, o->strict, paths)
                                      : record_test(*o, paths);
    });
}

}  // namespace openswarm
