#include "run_outputs.hpp"

#include <cstdio>
#include <string>
#include <system_error>

#include "commands/commands.hpp"

namespace fs = std::filesystem;

namespace openswarm {

namespace {

// What the simulator leaves in every world run's folder.
bool holds_a_run(const fs::path &out) {
    std::error_code ec;
    return fs::exists(out / "trajectories.csv", ec) || fs::exists(out / "viewer.html", ec);
}

}  // namespace

bool keep_last_run(const fs::path &out, bool out_given, const fs::path &world) {
    if (!holds_a_run(out)) return true;
    std::error_code ec;
    bool world_inside = fs::equivalent(world.parent_path(), out, ec);
    if (out_given || world_inside) {
        std::fprintf(stderr, "openswarm: %s holds the outputs of an earlier run: this run's replace them "
                             "(leave out --out to keep the last run beside the new one)\n",
                     out.string().c_str());
        return true;
    }
    fs::path last = out.string() + ".last";
    ec.clear();
    fs::remove_all(last, ec);
    if (!ec) fs::rename(out, last, ec);
    if (ec) {
        report("cannot keep the last run's outputs: moving " + out.string() + " to " + last.string() +
               " failed: " + ec.message() + "; move or remove " + out.string() + " yourself and run again");
        return false;
    }
    std::fprintf(stderr, "openswarm: the last run's outputs are kept in %s (the one before it is replaced); "
                         "this run writes %s\n",
                 last.string().c_str(), out.string().c_str());
    return true;
}

}  // namespace openswarm
