#include "process.hpp"

#include <cstdio>
#include <sys/wait.h>
#include <unistd.h>

namespace openswarm {

static int run(const std::vector<std::string> &argv, std::string *output) {
    int pipefd[2] = {-1, -1};
    if (output != nullptr && pipe(pipefd) != 0) return 127;
    std::fflush(stdout);
    pid_t pid = fork();
    if (pid < 0) return 127;
    if (pid == 0) {
        if (output != nullptr) {
            dup2(pipefd[1], STDOUT_FILENO);
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

int run_program(const std::vector<std::string> &argv) { return run(argv, nullptr); }

int capture_program(const std::vector<std::string> &argv, std::string &output) {
    return run(argv, &output);
}

}  // namespace openswarm
