// Copyright (c) 2026 The OpenSwarm authors. GPLv3 or later: runs the simulator, which links libsimavr.
#include "simulator_child.hpp"

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <signal.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

extern "C" int openswarm_sim_main(int argc, char **argv); // sim/src/main.c's main, renamed

// The wait for the child and the reading of its output are not
// instrumented: their counters say nothing about the simulator, and they
// vary from run to run (how often the wait polls depends on the machine's
// load), so that libFuzzer, reading them as coverage, kept other inputs
// on each run from the same seeds.
#define PLUMBING __attribute__((no_sanitize("coverage")))

// libFuzzer's edge counters (clang's inline-8bit-counters), bounded by the
// linker's section symbols.
extern "C" uint8_t __start___sancov_cntrs[] __attribute__((weak));
extern "C" uint8_t __stop___sancov_cntrs[] __attribute__((weak));

// A run ends within this much wall time or is a hang: inputs run for
// milliseconds of simulated time, a few hundred ms under the sanitizers on
// a loaded machine.
static constexpr double WALL_LIMIT_S = 30;

// Findings are told on the standard error the process started with:
// libFuzzer's -close_fd_mask=2 silences fd 2 after this initialiser ran.
static const int told_fd = dup(2);

static void tell(const std::string &text) {
    if (told_fd < 0) return;
    for (size_t done = 0; done < text.size();) {
        ssize_t n = write(told_fd, text.data() + done, text.size() - done);
        if (n <= 0) return;
        done += (size_t)n;
    }
}

[[noreturn]] static void fail_setup(const char *what) {
    tell(std::string("simulator_child: ") + what + ": " + std::strerror(errno) + "\n");
    std::abort();
}

static size_t counter_count() {
    if (__start___sancov_cntrs == nullptr || __stop___sancov_cntrs == nullptr) return 0;
    return (size_t)(__stop___sancov_cntrs - __start___sancov_cntrs);
}

// What the child hands back: whether main returned, and its status.
struct ChildResult {
    int returned;
    int status;
    uint8_t counters[]; // its coverage, counter_count() of them, as it ended
};

struct ChildLink {
    ChildResult *result;
    int output_fd; // a memory file: the child's standard output and error
};

static const ChildLink &child_link() {
    static const ChildLink link = [] {
        void *shared = mmap(nullptr, sizeof(ChildResult) + counter_count(), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
        if (shared == MAP_FAILED) fail_setup("mapping the child's result");
        int fd = memfd_create("openswarm-sim-output", MFD_CLOEXEC);
        if (fd < 0) fail_setup("making the output's memory file");
        return ChildLink{(ChildResult *)shared, fd};
    }();
    return link;
}

// What the child ran counts as this process's coverage, which libFuzzer
// reads when the input is done (the counters saturate at 255).
static void count_child_coverage(const uint8_t *child) {
    for (size_t i = 0; i < counter_count(); i++) {
        unsigned sum = __start___sancov_cntrs[i] + child[i];
        __start___sancov_cntrs[i] = (uint8_t)(sum > 255 ? 255 : sum);
    }
}

[[noreturn]] static void run_child(const std::vector<std::string> &args, const ChildLink &link) {
    std::memset(__start___sancov_cntrs, 0, counter_count()); // the parent's own count stays its
    dup2(link.output_fd, 1);
    dup2(link.output_fd, 2);
    std::vector<char *> argv;
    static char program[] = "openswarm-sim";
    argv.push_back(program);
    for (const std::string &a : args) argv.push_back(const_cast<char *>(a.c_str()));
    argv.push_back(nullptr);
    link.result->status = openswarm_sim_main((int)args.size() + 1, argv.data());
    std::memcpy(link.result->counters, __start___sancov_cntrs, counter_count());
    link.result->returned = 1;
    _exit(0); // no exit handlers: LeakSanitizer would report what a program may leave to exit
}

PLUMBING static std::string output_of(int fd) {
    std::string text;
    char chunk[4096];
    for (off_t at = 0;;) {
        ssize_t n = pread(fd, chunk, sizeof chunk, at);
        if (n <= 0) return text;
        text.append(chunk, (size_t)n);
        at += n;
    }
}

// The child's wait status, or -1 once the wall-time limit passed (the
// child killed).
PLUMBING static int wait_for(pid_t child) {
    auto started = std::chrono::steady_clock::now();
    auto pause = std::chrono::microseconds(20);
    for (;;) {
        int how;
        pid_t done = waitpid(child, &how, WNOHANG);
        if (done == child) return how;
        if (done < 0 && errno != EINTR) fail_setup("waiting for the simulator");
        if (std::chrono::steady_clock::now() - started > std::chrono::duration<double>(WALL_LIMIT_S)) {
            kill(child, SIGKILL);
            waitpid(child, &how, 0);
            return -1;
        }
        std::this_thread::sleep_for(pause);
        if (pause < std::chrono::milliseconds(2)) pause *= 2;
    }
}

PLUMBING SimulatorRun run_simulator(const std::vector<std::string> &args) {
    const ChildLink &link = child_link();
    link.result->returned = 0;
    link.result->status = 0;
    if (ftruncate(link.output_fd, 0) != 0 || lseek(link.output_fd, 0, SEEK_SET) != 0)
        fail_setup("emptying the output's memory file");
    pid_t child = fork();
    if (child < 0) fail_setup("fork");
    if (child == 0) run_child(args, link);
    int how = wait_for(child);
    SimulatorRun run{link.result->status, output_of(link.output_fd)};
    if (how == -1) simulator_finding("no end within " + std::to_string((int)WALL_LIMIT_S) + " s of wall time", run);
    if (WIFSIGNALED(how)) simulator_finding("killed by signal " + std::to_string(WTERMSIG(how)), run);
    if (!link.result->returned)
        simulator_finding("exited with status " + std::to_string(WEXITSTATUS(how)) +
                              " from inside the run (a sanitizer's report, or exit())", run);
    count_child_coverage(link.result->counters);
    return run;
}

void simulator_finding(const std::string &what, const SimulatorRun &run) {
    tell(run.output + "\nsimulator_child: the simulator " + what +
         " (its output above; the input is kept as crash-*: run the fuzzer on it alone to see it again)\n");
    std::abort();
}
