#include "process.hpp"

#include <array>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cerrno>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

namespace openswarm {

namespace {

// The programs running now, to pass a signal on to (0: a free place);
// lock-free atomics are safe to read in a signal handler.
std::array<std::atomic<pid_t>, 256> running{};
std::atomic<int> caught{0};

void pass_on(int signal_number, siginfo_t *info, void *) {
    int none = 0;
    caught.compare_exchange_strong(none, signal_number);
    // si_code > 0: sent by the kernel, as a terminal's Ctrl-C is, to the
    // whole foreground group: the programs have it already.
    if (info != nullptr && info->si_code > 0) return;
    for (auto &pid : running)
        if (pid.load() > 0) kill(pid.load(), signal_number);
}

// A program started: noted while it runs, for pass_on.
struct Running {
    std::atomic<pid_t> *place = nullptr;
    explicit Running(pid_t pid) {
        for (auto &p : running) {
            pid_t free = 0;
            if (p.compare_exchange_strong(free, pid)) {
                place = &p;
                return;
            }
        }
    }
    ~Running() {
        if (place != nullptr) place->store(0);
    }
};

// Where the child's standard output (and error) go.
enum class Streams { inherit, stdout_to_stderr, capture_stdout, capture_both };

[[noreturn]] void exec_child(const std::vector<std::string> &argv) {
    std::vector<char *> args;
    for (const auto &a : argv) args.push_back(const_cast<char *>(a.c_str()));
    args.push_back(nullptr);
    execvp(args[0], args.data());
    std::fprintf(stderr, "openswarm: cannot run %s\n", args[0]);
    _exit(127);
}

int exit_status_of(pid_t pid) {
    int status = 0;
    pid_t done;
    while ((done = waitpid(pid, &status, 0)) < 0 && errno == EINTR) continue;
    if (done < 0) return 127;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

int run(const std::vector<std::string> &argv, Streams streams, std::string *output) {
    int pipefd[2] = {-1, -1};
    if (output != nullptr && pipe(pipefd) != 0) return 127;
    std::fflush(stdout);
    pid_t pid = fork();
    if (pid < 0) return 127;
    if (pid == 0) {
        if (streams == Streams::stdout_to_stderr) dup2(STDERR_FILENO, STDOUT_FILENO);
        if (output != nullptr) {
            dup2(pipefd[1], STDOUT_FILENO);
            if (streams == Streams::capture_both) dup2(pipefd[1], STDERR_FILENO);
            close(pipefd[0]);
            close(pipefd[1]);
        }
        exec_child(argv);
    }
    Running noted(pid);
    if (output != nullptr) {
        close(pipefd[1]);
        char buf[4096];
        ssize_t n;
        while ((n = read(pipefd[0], buf, sizeof buf)) > 0) output->append(buf, (size_t)n);
        close(pipefd[0]);
    }
    return exit_status_of(pid);
}

}  // namespace

void pass_interrupts_on() {
    struct sigaction a {};
    a.sa_sigaction = pass_on;
    a.sa_flags = SA_SIGINFO | SA_RESTART; // reads and waits go on after it
    sigemptyset(&a.sa_mask);
    // Started with SIGINT ignored (a script's background job): it stays
    // ignored, as the shell meant, and the programs inherit that.
    struct sigaction was {};
    if (sigaction(SIGINT, nullptr, &was) == 0 && was.sa_handler != SIG_IGN) sigaction(SIGINT, &a, nullptr);
    sigaction(SIGTERM, &a, nullptr);
}

int interrupted() { return caught.load(); }

bool interrupted_status(int status) { return status == 128 + SIGINT || status == 128 + SIGTERM; }

std::string simulator_failure(int status) {
    switch (status) {
    case 2: return "the simulator refused its input (its message is above)";
    case 3: return "the firmware crashed (above): `openswarm run --gdb 1234` shows where";
    case 4: return "the firmware did not stop by itself in the time given";
    case 5: return "a robot jumped to the bootloader (a BOOT message)";
    case 6: return "the firmware reported a kernel fault, a stack overflowed or a pointer wrote "
                   "into the CPU's registers (above: which, when, and what to do): the run fails";
    case 7: return "the firmware hung with interrupts masked (above: since when, where)";
    case 8: return "the run ended with warnings (above: each with its fix), and --strict makes them "
                   "errors; fix them, or run without --strict";
    case 128 + SIGINT:
    case 128 + SIGTERM:
        return std::string("the run was interrupted by ") + (status == 128 + SIGINT ? "SIGINT" : "SIGTERM") +
               " (above: at what simulated time, and the files it wrote for the run so far)";
    default: return "the firmware stopped with status " + std::to_string(status);
    }
}

int run_program(const std::vector<std::string> &argv) {
    return run(argv, Streams::inherit, nullptr);
}

int run_program_to_stderr(const std::vector<std::string> &argv) {
    return run(argv, Streams::stdout_to_stderr, nullptr);
}

int capture_program(const std::vector<std::string> &argv, std::string &output) {
    return run(argv, Streams::capture_stdout, &output);
}

int capture_program_and_errors(const std::vector<std::string> &argv, std::string &output) {
    return run(argv, Streams::capture_both, &output);
}

int run_program_lines(const std::vector<std::string> &argv,
                      const std::function<void(const std::string &)> &on_line,
                      double timeout_seconds, bool with_errors) {
    int pipefd[2];
    if (pipe(pipefd) != 0) return 127;
    std::fflush(stdout);
    pid_t pid = fork();
    if (pid < 0) return 127;
    if (pid == 0) {
        dup2(pipefd[1], STDOUT_FILENO);
        if (with_errors) dup2(pipefd[1], STDERR_FILENO);
        close(pipefd[0]);
        close(pipefd[1]);
        exec_child(argv);
    }
    Running noted(pid);
    close(pipefd[1]);
    using clock = std::chrono::steady_clock;
    const auto deadline = clock::now() + std::chrono::duration<double>(timeout_seconds);
    std::string pending;
    bool timed_out = false;
    for (;;) {
        int wait_ms = -1;
        if (timeout_seconds > 0) {
            auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - clock::now());
            if (left.count() <= 0) {
                timed_out = true;
                break;
            }
            wait_ms = (int)left.count();
        }
        struct pollfd p = {pipefd[0], POLLIN, 0};
        if (poll(&p, 1, wait_ms) == 0) continue;
        char buf[4096];
        ssize_t n = read(pipefd[0], buf, sizeof buf);
        if (n <= 0) break;
        pending.append(buf, (size_t)n);
        for (size_t end; (end = pending.find('\n')) != std::string::npos;) {
            on_line(pending.substr(0, end));
            pending.erase(0, end + 1);
        }
    }
    if (!pending.empty() && !timed_out) on_line(pending);
    if (timed_out) kill(pid, SIGKILL);
    close(pipefd[0]);
    int status = exit_status_of(pid);
    return timed_out ? 124 : status;
}

}  // namespace openswarm
