#include "trial_outcome.hpp"

#include "fingerprint.hpp"

#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using nlohmann::json;

namespace openswarm {

std::string file_fingerprint(const fs::path &file) {
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) return "";
    std::ifstream in(file, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return fingerprint(text.str());
}

bool write_text(const fs::path &file, const std::string &text) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out << text;
    out.close();
    return (bool)out;
}

void write_outcome(const fs::path &dir, const json &outcome) {
    fs::path temporary = dir / "outcome.json.part";
    std::error_code ec;
    if (write_text(temporary, outcome.dump(2) + "\n")) fs::rename(temporary, dir / "outcome.json", ec);
}

json read_outcome(const fs::path &dir) {
    std::ifstream in(dir / "outcome.json");
    json outcome = json::parse(in, nullptr, false);
    return !outcome.is_discarded() && outcome.is_object() ? outcome : json::object();
}

void forget_outcome(const fs::path &dir) {
    std::error_code ec;
    fs::remove(dir / "outcome.json", ec);
}

}  // namespace openswarm
