// The world.json reader's test fixture (sim/src/world/world_file.cpp):
// writes a world into a fresh folder, loads it, and returns the message.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "world/world_spec.h"

namespace fs = std::filesystem;

class WorldFile : public ::testing::Test {
  protected:
    fs::path dir;

    void SetUp() override {
        std::string pattern = (fs::temp_directory_path() / "world_file_XXXXXX").string();
        ASSERT_NE(mkdtemp(pattern.data()), nullptr);
        dir = pattern;
    }
    void TearDown() override { fs::remove_all(dir); }

    std::string write(const std::string &name, const std::string &text) {
        fs::path p = dir / name;
        fs::create_directories(p.parent_path());
        std::ofstream(p, std::ios::binary) << text;
        return p.string();
    }

    // Loads text; on failure returns the message (stderr), else "".
    std::string load(const std::string &text, world_spec *w, const std::string &name = "world.json") {
        std::string path = write(name, text);
        testing::internal::CaptureStderr();
        int status = world_spec_load(path.c_str(), w);
        std::string err = testing::internal::GetCapturedStderr();
        EXPECT_EQ(status == 0, err.empty()) << err;
        // Messages name the file as given: drop the folder for comparisons.
        size_t at = err.find(path);
        if (at != std::string::npos) err.replace(at, path.size(), name);
        return err;
    }

    std::string error_of(const std::string &text) {
        world_spec w{};
        std::string err = load(text, &w);
        if (err.empty()) world_spec_free(&w);
        return err;
    }
};
