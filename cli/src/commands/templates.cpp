// openswarm templates: what `openswarm new` can start from.
#include "../suggest.hpp"
#include "../templates.hpp"
#include "commands.hpp"

namespace openswarm {

void add_templates_command(CLI::App &app, const Paths &paths) {
    CLI::App *cmd = app.add_subcommand("templates", "List the app templates");
    cmd->callback([&paths] {
        for (const auto &t : list_templates(paths.templates()))
            std::printf("%-10s %s [%s]\n", t.name.c_str(), t.description.c_str(), join(t.ports).c_str());
        exit_code = EXIT_OK;
    });
}

}  // namespace openswarm
