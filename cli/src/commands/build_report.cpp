// How `openswarm build` reports what it built (build_report.hpp).
#include "build_report.hpp"

#include <cmath>
#include <cstdio>

#include <nlohmann/json.hpp>

#include "commands.hpp"

namespace fs = std::filesystem;

namespace openswarm {

namespace {

std::string bar(unsigned used, unsigned total) {
    const int width = 20;
    int filled = total ? (int)((unsigned long)used * width / total) : 0;
    if (filled > width) filled = width;
    char percent[16];
    std::snprintf(percent, sizeof percent, "%5.1f%%", total ? 100.0 * used / total : 0.0);
    return "[" + std::string(filled, '=') + std::string(width - filled, ' ') + "] " + percent +
           " (" + std::to_string(used) + " of " + std::to_string(total) + " bytes)";
}

// A share's bytes in the image: its percentage of the attribution build
// applied to the image's total (LTO shrinks the parts unevenly: approximate).
long approximate(double percent, unsigned image_bytes) {
    return std::lround(percent * image_bytes / 100.0);
}

double one_decimal(double x) { return std::round(x * 10.0) / 10.0; }

}  // namespace

void print_build_summary(const BuildResult &r, const std::vector<Share> &shares, const std::string &why) {
    const PortInfo &info = port_info(r.port);
    if (r.native) {
        std::printf("Built %s for %s, native: for the host, a robot of openswarm-sim's native mode "
                    "(`openswarm run --native`, docs/world.md)\n", r.image.string().c_str(), r.port.c_str());
        return;
    }
    if (r.qemu) {
        std::printf("Built %s for %s, qemu: the e-puck2's image, a robot of a world with \"fidelity\": \"qemu\" "
                    "(docs/world.md)\n", r.image.string().c_str(), r.port.c_str());
        return;
    }
    if (info.flash_bytes == 0) { // a host program: no memory of a robot's to fill
        std::printf("Built %s for %s: run it in a world, `openswarm run --world FILE` (docs/world.md)\n",
                    r.image.string().c_str(), r.port.c_str());
        return;
    }
    std::printf("Flash %s\nRAM   %s\n", bar(r.flash, r.flash_total).c_str(),
                bar(r.ram, info.ram_bytes).c_str());
    if (shares.empty()) {
        std::printf("Shares of kernel and app: unavailable, %s\n", why.c_str());
    } else {
        std::printf("Shares, approximate (measured without link-time optimisation, bytes scaled to "
                    "this image):\n");
        std::printf("  %-38s %15s %15s\n", "", "flash", "RAM");
        for (const Share &s : shares)
            std::printf("  %-38s %5.1f%% ~%6ld  %5.1f%% ~%6ld\n", s.name.c_str(), s.flash_percent,
                        approximate(s.flash_percent, r.flash), s.ram_percent,
                        approximate(s.ram_percent, r.ram));
    }
    std::printf("Built %s for %s\n", r.image.string().c_str(), r.port.c_str());
    if (r.robot) {
        fs::path bin = fs::path(r.robot->image).replace_extension(".bin");
        const FlashPlacement &at = r.robot->placement;
        std::printf("Robot image (flash from %s, %s: openswarm.json's \"epuck2\": {\"bootloader\": "
                    "\"%s\"}):\nFlash %s\nRAM   %s\n"
                    "Built %s and %s: ports/epuck/README.md says how to flash it\n",
                    hex_address(at.origin).c_str(), at.what.c_str(), at.bootloader.c_str(),
                    bar(r.robot->flash, at.bytes).c_str(), bar(r.robot->ram, info.ram_bytes).c_str(),
                    r.robot->image.string().c_str(), bin.string().c_str());
    }
}

void print_build_json(const BuildResult &r, const std::vector<Share> &shares, const std::string &why) {
    const PortInfo &info = port_info(r.port);
    nlohmann::ordered_json j = {
        {"image", r.image.string()},       {"port", r.port}, {"native", r.native}, {"qemu", r.qemu}, {"flash", r.flash},
        {"flash_total", r.flash_total},    {"ram", r.ram},   {"ram_total", info.ram_bytes}};
    j["parameters"] = r.parameters;
    if (shares.empty()) {
        j["share"] = nullptr;
        j["share_unavailable"] = why;
    } else {
        nlohmann::ordered_json share = {{"approximate", true},
                                        {"measured_on", "a build without link-time optimisation"}};
        for (const Share &s : shares)
            share[s.key] = {{"flash_percent", one_decimal(s.flash_percent)},
                            {"ram_percent", one_decimal(s.ram_percent)},
                            {"flash_bytes_approx", approximate(s.flash_percent, r.flash)},
                            {"ram_bytes_approx", approximate(s.ram_percent, r.ram)}};
        j["share"] = share;
    }
    if (r.robot)
        j["robot"] = {{"image", r.robot->image.string()},
                      {"bin", fs::path(r.robot->image).replace_extension(".bin").string()},
                      {"bootloader", r.robot->placement.bootloader},
                      {"flash_origin", r.robot->placement.origin},
                      {"flash", r.robot->flash},
                      {"flash_total", r.robot->placement.bytes},
                      {"ram", r.robot->ram}};
    std::printf("%s\n", j.dump().c_str());
}

// A failed build --json: its errors (also said on standard error) as JSON
// on standard output, where the caller reads the result (issue 31: it
// printed nothing there).
void print_build_json_failure() {
    nlohmann::ordered_json j = {{"error", reported_messages()}, {"exit_code", exit_code}};
    std::printf("%s\n", j.dump().c_str());
}

}  // namespace openswarm
