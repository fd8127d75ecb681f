// openswarm clean: remove the app's build folder, where build, run, test
// and size write (images, the files generated from openswarm.json, CMake's
// caches); nothing of the app's own.
#include <filesystem>

#include "commands.hpp"

namespace fs = std::filesystem;

namespace openswarm {

namespace {

// Files and bytes under folder, for the line that says what went.
void measure(const fs::path &folder, size_t &files, std::uintmax_t &bytes) {
    std::error_code error;
    for (fs::recursive_directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
        if (!it->is_regular_file(error)) continue;
        files++;
        bytes += it->file_size(error);
    }
}

int clean(const fs::path &dir) {
    if (!fs::exists(dir / "openswarm.json")) {
        report((dir / "openswarm.json").string() + ": not found; `openswarm clean` removes an app's build "
               "folder: run it in an app's folder, or give it with -C DIR");
        return EXIT_USAGE;
    }
    fs::path build = dir / "build";
    std::error_code error;
    if (!fs::exists(fs::symlink_status(build, error))) {
        std::printf("Nothing to remove: %s does not exist\n", build.string().c_str());
        return EXIT_OK;
    }
    size_t files = 0;
    std::uintmax_t bytes = 0;
    measure(build, files, bytes);
    fs::remove_all(build, error);
    if (error) {
        report("could not remove all of " + build.string() + " (" + error.message() +
               "); check its permissions, then run `openswarm clean` again");
        return EXIT_FAILED;
    }
    std::printf("Removed %s (%zu files, %.1f MB); the next `openswarm build` makes it again\n",
                build.string().c_str(), files, (double)bytes / 1e6);
    return EXIT_OK;
}

}  // namespace

void add_clean_command(CLI::App &app, const Paths &) {
    auto dir = std::make_shared<std::string>(".");
    CLI::App *cmd = app.add_subcommand(
        "clean", "Remove the app's build folder (images, generated files, CMake's caches)");
    cmd->add_option("-C,--directory", *dir, "the app's folder")->capture_default_str();
    cmd->callback([dir] { exit_code = clean(*dir); });
}

}  // namespace openswarm
