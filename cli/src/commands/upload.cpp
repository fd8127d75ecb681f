// openswarm upload: the app's image onto the robot - a Kilobot's .hex
// through the overhead controller (kilobot_ohc.hpp), an e-puck2's ELF
// through its programmer's GDB server (epuck2_programmer.hpp). Built first
// unless a file is given.
#include <cstdio>
#include <filesystem>

#include "../epuck2_programmer.hpp"
#include "../intel_hex.hpp"
#include "../kilobot_ohc.hpp"
#include "build.hpp"
#include "commands.hpp"

namespace fs = std::filesystem;

namespace openswarm {

namespace {

struct UploadOptions {
    std::string dir = ".";
    std::string port;   // the robot; "" = the app's
    std::string device; // the serial port; "" = the only one there is
    std::string file;   // an image to send instead of building the app
    OhcUpload ohc;
    double timeout = 0; // 0: the robot's own (OhcUpload's; EPUCK2_PROGRAMMING_SECONDS)
};

// The robot a given file is for, from its kind: a .hex is a Kilobot's
// (KiloGUI's), an ELF an e-puck2's.
std::string port_of_file(const std::string &file) {
    std::string ext = fs::path(file).extension().string();
    if (ext == ".hex") return "kilobot";
    if (ext == ".elf") return "epuck2";
    return "";
}

void show_page(unsigned round, unsigned page, unsigned pages) {
    if (page + 1 == pages) std::printf("  round %u: %u pages sent\n", round, pages);
    std::fflush(stdout);
}

int upload_kilobot(const UploadOptions &o, const fs::path &hex) {
    std::vector<uint8_t> flash;
    try {
        flash = read_intel_hex(hex);
    } catch (const HexError &e) {
        report(e.what());
        return EXIT_USAGE;
    }
    unsigned pages = (unsigned)((flash.size() + OHC_PAGE_BYTES - 1) / OHC_PAGE_BYTES);
    if (pages > OHC_MAX_PAGES) {
        report(hex.string() + " fills " + std::to_string(flash.size()) + " bytes of flash, " +
               std::to_string(pages) + " pages; the overhead controller sends at most " +
               std::to_string(OHC_MAX_PAGES) + " pages of " + std::to_string(OHC_PAGE_BYTES) + " bytes (" +
               std::to_string(OHC_MAX_PAGES * OHC_PAGE_BYTES) +
               " bytes): make the app smaller (`openswarm size` shows where the flash goes)");
        return EXIT_USAGE;
    }
    std::string device = serial_port_to_use(o.device);
    SerialPort port(device, OHC_BAUD);
    OhcUpload how = o.ohc;
    if (o.timeout > 0) how.timeout = o.timeout;
    std::printf("Uploading %s (%zu bytes, %u pages of %u) through the overhead controller on %s: "
                "Bootload, then %u round%s of pages %.2f s apart\n",
                hex.string().c_str(), flash.size(), pages, OHC_PAGE_BYTES, device.c_str(), o.ohc.rounds,
                o.ohc.rounds == 1 ? "" : "s", o.ohc.page_gap);
    std::fflush(stdout);
    upload_through_ohc(port, flash, how, show_page);
    std::printf("Sent; the controller is stopped. Robots that got every page run the app when you send "
                "Run (KiloGUI's Run); one that missed a page keeps blinking in its bootloader: upload "
                "again, or give --rounds 3\n");
    return EXIT_OK;
}

int upload(const UploadOptions &o, const Paths &paths) {
    fs::path image = o.file;
    std::string port = o.port;
    if (!o.file.empty()) {
        if (port.empty()) port = port_of_file(o.file);
        if (port.empty()) {
            report(o.file + ": neither a .hex (a Kilobot's) nor an .elf (an e-puck2's); give --port "
                            "kilobot or --port epuck2, or the image `openswarm build` made");
            return EXIT_USAGE;
        }
    } else {
        auto built = build_app(paths, o.dir, o.port, Progress::brief);
        if (!built) return exit_code;
        port = built->port;
        image = port == "kilobot" ? fs::path(built->image).replace_extension(".hex")
                                  : built->robot ? built->robot->image : built->image;
    }
    if (port == "kilobot") return upload_kilobot(o, image);
    if (port == "epuck2") {
        std::string device = serial_port_to_use(o.device);
        return program_epuck2(image, device, o.timeout > 0 ? o.timeout : EPUCK2_PROGRAMMING_SECONDS);
    }
    report("nothing uploads to the " + port + " port's robots from here: `openswarm upload` knows the "
           "Kilobot (through the overhead controller) and the e-puck2 (through its programmer); give "
           "--port kilobot or --port epuck2");
    return EXIT_USAGE;
}

}  // namespace

void add_upload_command(CLI::App &app, const Paths &paths) {
    auto o = std::make_shared<UploadOptions>();
    CLI::App *cmd = app.add_subcommand(
        "upload", "Build the app and put it on the robot: a Kilobot through the overhead controller, "
                  "an e-puck2 through its programmer");
    cmd->add_option("file", o->file, "an image to send instead of building the app (.hex: Kilobot, .elf: e-puck2)");
    cmd->add_option("-C,--directory", o->dir, "the app's folder")->capture_default_str();
    cmd->add_option("-p,--port", o->port, "the robot: kilobot or epuck2 (default: the app's)");
    cmd->add_option("-d,--device", o->device,
                    "the serial port: the overhead controller's or the e-puck2 programmer's "
                    "(default: the only /dev/ttyUSB* or /dev/ttyACM* there is)");
    cmd->add_option("--rounds", o->ohc.rounds, "Kilobot: send the whole image this many times, for robots "
                                               "that miss a page")
        ->capture_default_str()
        ->check(CLI::Range(1, 20));
    cmd->add_option("--page-gap", o->ohc.page_gap,
                    "Kilobot: seconds between packets (the controller's time to send a page by infrared)")
        ->capture_default_str()
        ->check(finite_seconds("--page-gap", 0, 5, "0.13"));
    cmd->add_option("--timeout", o->timeout,
                    "seconds to wait for the port (Kilobot: to take bytes, 5; e-puck2: the whole programming, 120)")
        ->check(finite_seconds("--timeout", 0.1, 600, "30"));
    cmd->callback([o, &paths] {
        try {
            exit_code = upload(*o, paths);
        } catch (const SerialError &e) {
            report(e.what());
            exit_code = e.bad_input ? EXIT_USAGE : EXIT_FAILED;
        }
    });
}

}  // namespace openswarm
