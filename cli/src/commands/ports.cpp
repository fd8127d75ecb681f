// openswarm ports: the robots there is a port for.
#include <nlohmann/json.hpp>

#include "../ports.hpp"
#include "commands.hpp"

namespace openswarm {

void add_ports_command(CLI::App &app, const Paths &) {
    auto json = std::make_shared<bool>(false);
    CLI::App *cmd = app.add_subcommand("ports", "List the robots OpenSwarm builds for");
    cmd->add_flag("--json", *json, "print them as JSON");
    cmd->callback([json] {
        if (*json) {
            nlohmann::json out = nlohmann::json::array();
            for (const auto &p : ports())
                out.push_back({{"name", p.name}, {"description", p.description},
                               {"flash_bytes", p.flash_bytes}, {"ram_bytes", p.ram_bytes}});
            std::printf("%s\n", out.dump(2).c_str());
        } else {
            for (const auto &p : ports()) std::printf("%-10s %s\n", p.name.c_str(), p.description.c_str());
        }
        exit_code = EXIT_OK;
    });
}

}  // namespace openswarm
