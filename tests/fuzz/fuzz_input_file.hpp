// A fuzzer's input as a file: the readers under test take paths.
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

// A folder of this process's own, made once, removed at exit. Its name
// is as long whatever the pid: the input's path reaches the code under
// test (the simulator quotes it for a shell, prints it), whose loops over
// it would otherwise run a different number of times from one run to the
// next - coverage libFuzzer follows, so that a rerun from the same seeds
// kept other inputs.
inline std::string fixed_width_pid() {
    char text[16];
    std::snprintf(text, sizeof text, "%010ld", (long)getpid());
    return text;
}

struct FuzzDir {
    std::filesystem::path path = std::filesystem::temp_directory_path() / ("openswarm-fuzz-" + fixed_width_pid());
    FuzzDir() { std::filesystem::create_directories(path); }
    ~FuzzDir() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
};

inline const std::filesystem::path &fuzz_dir() {
    static const FuzzDir dir;
    return dir.path;
}

inline std::filesystem::path write_input(const std::string &name, const uint8_t *data, size_t size) {
    std::filesystem::path p = fuzz_dir() / name;
    std::ofstream(p, std::ios::binary).write(reinterpret_cast<const char *>(data), (std::streamsize)size);
    return p;
}
