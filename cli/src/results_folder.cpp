#include "results_folder.hpp"

#include <string>
#include <system_error>

#include "commands/commands.hpp"

namespace fs = std::filesystem;

namespace openswarm {

bool prepare_results_folder(const fs::path &out, const Ranks &ranks) {
    auto report = [&](const std::string &message) {
        if (ranks.rank() == 0) openswarm::report(message);
    };
    std::error_code ec;
    fs::file_status st = fs::status(out, ec);
    if (fs::exists(st) && !fs::is_directory(st)) {
        report("--out " + out.string() + ": it is a file, not a folder; the results go into a folder: "
               "give another --out (a folder, new or existing)");
        return false;
    }
    ec.clear();
    fs::create_directories(out, ec);
    if (ec) {
        report("--out " + out.string() + ": cannot create the results' folder: " + ec.message() +
               "; give an --out folder you can write to");
        return false;
    }
    return true;
}

}  // namespace openswarm
