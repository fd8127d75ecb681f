#include "process.hpp"

#include <cstdio>
#include <sys/wait.h>
#include <unistd.h>

namespace openswarm {

namespace {

// Where the child's standard output (and error) go.
enum class Streams { inherit, stdout_to_stderr, capture_stdout, capture_both };

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
        std::vector<char *> args;
        for (const auto &a : argv) args.push_back(const_cast<char *>(a.c_str()));
        args.push_back(nullptr);
        execvp(args[0], args.data());
        std::fprintf(stderr, "openswarm: cannot run %s\n", args[0]);
        _exit(127);
    }
    if (output != nullptr) {
        close(pipefd[1]);
        char buf[4096];
        ssize_t n;
        while ((n = read(pipefd[0], buf, sizeof buf)) > 0) output->append(buf, (size_t)n);
        close(pipefd[0]);
    }
    int status = 0;
    if (waitpid(pid, &status, 0) < 0) return 127;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace

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

}  // namespace openswarm
