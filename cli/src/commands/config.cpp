// openswarm config check|show: validate openswarm.json and print what it
// resolves to.
#include <cctype>

#include "../app_config.hpp"
#include "../app_project.hpp"
#include "../app_sources.hpp"
#include "../generate.hpp"
#include "../ports.hpp"
#include "commands.hpp"

namespace openswarm {

void add_config_command(CLI::App &app, const Paths &) {
    auto dir = std::make_shared<std::string>(".");
    auto port = std::make_shared<std::string>();
    CLI::App *cmd = app.add_subcommand("config", "Check or show the app's openswarm.json");
    cmd->require_subcommand(1);
    for (const char *name : {"check", "show"}) {
        bool show = std::string(name) == "show";
        CLI::App *sub = cmd->add_subcommand(name, show ? "Print what openswarm.json resolves to"
                                                       : "Validate openswarm.json");
        sub->add_option("-C,--directory", *dir, "the app's folder")->capture_default_str();
        sub->add_option("-p,--port", *port, "as built for this port (`build --port`; default: the app's)");
        sub->callback([dir, port, show] {
            if (!port->empty() && !is_port(*port)) {
                report(unknown_port_message(*port));
                exit_code = EXIT_USAGE;
                return;
            }
            try {
                AppConfig c = load_app_config(*dir, *port);
                check_app_project_name(*dir, c);
                // What the build would refuse (pools, limits, names) is refused here.
                check_app_files(c, libraries_used(*dir, port_info(c.port)));
                if (show) {
                    const PortInfo &p = port_info(c.port);
                    std::printf("name  %s\nport  %s (%s)\nimage build/%s/%s.elf\n", c.name.c_str(),
                                c.port.c_str(), p.description.c_str(), c.port.c_str(), c.name.c_str());
                    if (c.port == "epuck2") {
                        const FlashPlacement &at = robot_placement(c);
                        std::printf("robot image build/epuck2/%s-robot.elf at %s, %u bytes of flash (%s: "
                                    "epuck2.bootloader \"%s\")\n",
                                    c.name.c_str(), hex_address(at.origin).c_str(), at.bytes, at.what.c_str(),
                                    at.bootloader.c_str());
                    }
                    std::printf("scheduler %s, time slice %ld ms\n",
                                c.scheduler.empty() ? "round-robin" : c.scheduler.c_str(),
                                c.time_slice_ms ? c.time_slice_ms : 10L);
                    for (const auto &[key, value] : c.kernel) {
                        if (is_kernel_switch(key))
                            std::printf("kernel.%s %s\n", key.c_str(), value ? "true" : "false");
                        else
                            std::printf("kernel.%s %ld\n", key.c_str(), value);
                    }
                    for (size_t i = 0; i < c.events.size(); i++) {
                        std::string macro = c.events[i].name;
                        for (auto &ch : macro) ch = (char)std::toupper((unsigned char)ch);
                        std::printf("event EV_%s (id SYS_EVENT_FIRST_FREE + %zu), %u bytes\n", macro.c_str(), i,
                                    c.events[i].size);
                    }
                    for (const auto &d : c.devices) {
                        std::printf("device %s: processor %s", d.device.c_str(), d.processor.c_str());
                        for (const auto &[k, v] : d.params) std::printf(", %s %ld", k.c_str(), v);
                        if (!d.points.empty()) std::printf(", points");
                        for (const auto &[raw, value] : d.points) std::printf(" %ld->%ld", raw, value);
                        std::printf("\n");
                    }
                    for (const auto &t : c.threads)
                        std::printf("thread %s, stack %u bytes%s, priority %u\n", t.entry.c_str(), t.stack,
                                    t.stack ? "" : " (default)", t.priority);
                    for (const auto &a : c.parameters) {
                        char at[32] = "";
                        if (a.in_eeprom) std::snprintf(at, sizeof at, " at EEPROM 0x%03X", a.eeprom_address);
                        std::printf("parameter %s %ld (%ld..%ld)%s%s%s\n", a.name.c_str(), a.value, a.min, a.max, at,
                                    a.doc.empty() ? "" : ": ", a.doc.c_str());
                    }
                } else {
                    std::printf("%s is valid%s\n", c.file.string().c_str(),
                                port->empty() ? "" : (" for " + *port).c_str());
                }
                exit_code = EXIT_OK;
            } catch (const ConfigError &e) {
                report(e.what());
                exit_code = EXIT_USAGE;
            }
        });
    }
}

}  // namespace openswarm
