// openswarm ports: the robots there is a port for.
#include "../ports.hpp"
#include "commands.hpp"

namespace openswarm {

void add_ports_command(CLI::App &app, const Paths &) {
    CLI::App *cmd = app.add_subcommand("ports", "List the robots OpenSwarm builds for");
    cmd->callback([] {
        for (const auto &p : ports()) std::printf("%-10s %s\n", p.name.c_str(), p.description.c_str());
        exit_code = EXIT_OK;
    });
}

}  // namespace openswarm
