#include "script_metrics.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <poll.h>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

#include "../last_lines.hpp"
#include "metrics_error.hpp"

namespace fs = std::filesystem;

namespace openswarm {

namespace {

const char *format_help = "expected NAME VALUE (a value at the run's end) or TIME_S,NAME,VALUE (a value at a "
                          "time), one a line (docs/experiments.md, \"Your own metric\")";

bool number(const std::string &text, double &v) {
    char *end;
    v = std::strtod(text.c_str(), &end);
    return !text.empty() && *end == '\0' && end != text.c_str() && std::isfinite(v);
}

bool name_ok(const std::string &name) {
    if (name.empty() || !std::isalpha((unsigned char)name[0])) return false;
    for (char c : name)
        if (!std::isalnum((unsigned char)c) && c != '_' && c != '.' && c != '-') return false;
    return true;
}

std::string trim(const std::string &s) {
    size_t b = s.find_first_not_of(" \t\r"), e = s.find_last_not_of(" \t\r");
    return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

// The last lines of text, each indented, at most lines of them.
std::string tail(const std::string &text, size_t lines) {
    std::string out;
    for (const std::string &line : last_lines(text, lines)) out += "\n    " + line;
    return out;
}

struct Finished {
    int status;  // exit status, or -1
    int signal;  // the signal that ended it, or 0
    std::string out, err;
};

// Runs argv with the environment's additions, reading its standard output
// and error as they come (both pipes at once: a script filling one while
// we wait on the other would hang).
Finished run_capturing(const std::vector<std::string> &argv, const std::vector<std::pair<std::string, std::string>> &env) {
    int out_pipe[2], err_pipe[2];
    if (pipe(out_pipe) != 0) throw MetricsError(std::string("cannot run a metric script: ") + std::strerror(errno), false);
    if (pipe(err_pipe) != 0) throw MetricsError(std::string("cannot run a metric script: ") + std::strerror(errno), false);
    std::fflush(stdout);
    pid_t pid = fork();
    if (pid < 0) throw MetricsError(std::string("cannot run a metric script: ") + std::strerror(errno), false);
    if (pid == 0) {
        dup2(out_pipe[1], STDOUT_FILENO);
        dup2(err_pipe[1], STDERR_FILENO);
        close(out_pipe[0]), close(out_pipe[1]), close(err_pipe[0]), close(err_pipe[1]);
        for (const auto &[k, v] : env) setenv(k.c_str(), v.c_str(), 1);
        std::vector<char *> args;
        for (const auto &a : argv) args.push_back(const_cast<char *>(a.c_str()));
        args.push_back(nullptr);
        execv(args[0], args.data());
        std::fprintf(stderr, "cannot start it: %s\n", std::strerror(errno));
        _exit(127);
    }
    close(out_pipe[1]);
    close(err_pipe[1]);
    Finished f{-1, 0, {}, {}};
    struct pollfd p[2] = {{out_pipe[0], POLLIN, 0}, {err_pipe[0], POLLIN, 0}};
    for (int open = 2; open > 0;) {
        if (poll(p, 2, -1) < 0) {
            if (errno == EINTR) continue;
            break;
        }
        for (int k = 0; k < 2; k++) {
            if (p[k].fd < 0 || !(p[k].revents & (POLLIN | POLLHUP | POLLERR))) continue;
            char buf[4096];
            ssize_t n = read(p[k].fd, buf, sizeof buf);
            if (n > 0) {
                (k == 0 ? f.out : f.err).append(buf, (size_t)n);
            } else {
                close(p[k].fd);
                p[k].fd = -1;
                open--;
            }
        }
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
    if (WIFEXITED(status)) f.status = WEXITSTATUS(status);
    else if (WIFSIGNALED(status)) f.signal = WTERMSIG(status);
    return f;
}

}  // namespace

std::vector<ScriptValue> parse_script_output(const std::string &script, const std::string &output) {
    std::vector<ScriptValue> values;
    std::istringstream in(output);
    long number_of_line = 0;
    for (std::string raw; std::getline(in, raw);) {
        number_of_line++;
        std::string line = trim(raw);
        if (line.empty() || line[0] == '#') continue;
        if (line == "time_s,name,value") continue;
        ScriptValue v{NAN, "", 0};
        bool ok = false;
        size_t comma = line.find(',');
        if (comma != std::string::npos) {
            size_t second = line.find(',', comma + 1);
            v.name = trim(line.substr(comma + 1, second == std::string::npos ? 0 : second - comma - 1));
            ok = second != std::string::npos && number(trim(line.substr(0, comma)), v.time_s) && v.time_s >= 0 &&
                 name_ok(v.name) && number(trim(line.substr(second + 1)), v.value);
        } else {
            size_t space = line.find_first_of(" \t");
            v.name = line.substr(0, space);
            ok = space != std::string::npos && name_ok(v.name) && number(trim(line.substr(space)), v.value);
        }
        if (!ok)
            throw MetricsError("metric script " + script + ": line " + std::to_string(number_of_line) +
                                   " of its output is \"" + line.substr(0, 80) + "\": " + format_help +
                                   "; names are letters, digits, '_', '.' or '-', starting with a letter",
                               false);
        values.push_back(v);
    }
    return values;
}

std::vector<ScriptValue> run_metric_script(const fs::path &script, const fs::path &run_dir, const fs::path &world) {
    std::error_code ec;
    fs::path path = script.has_parent_path() ? script : fs::path(".") / script;
    if (!fs::is_regular_file(path, ec))
        throw MetricsError("--script " + script.string() + ": no such file; give the path of an executable that " +
                           "prints the metric (docs/experiments.md, \"Your own metric\")");
    if (access(path.c_str(), X_OK) != 0)
        throw MetricsError("--script " + script.string() + ": not executable; make it so (chmod +x " +
                           script.string() + ") and start it with a #! line, e.g. #!/usr/bin/env python3");
    std::string by_hand = path.string() + " " + run_dir.string();
    Finished f = run_capturing({path.string(), run_dir.string()},
                               {{"OPENSWARM_RUN_DIR", run_dir.string()}, {"OPENSWARM_WORLD", world.string()}});
    std::string errors = f.err.empty() ? "" : "; the end of what it wrote on standard error:" + tail(f.err, 10);
    if (f.signal != 0)
        throw MetricsError("metric script " + script.string() + " was killed by signal " + std::to_string(f.signal) +
                               " (" + strsignal(f.signal) + ")" + errors + "\nRun it by hand to see why: " + by_hand,
                           false);
    if (f.status != 0)
        throw MetricsError("metric script " + script.string() + " failed with exit status " +
                               std::to_string(f.status) + errors + "\nRun it by hand to see why: " + by_hand,
                           false);
    auto values = parse_script_output(script.string(), f.out);
    if (values.empty())
        throw MetricsError("metric script " + script.string() + " printed no values: " + format_help +
                               "\nRun it by hand to see what it prints: " + by_hand,
                           false);
    return values;
}

}  // namespace openswarm
