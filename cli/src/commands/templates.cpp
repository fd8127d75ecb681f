// openswarm templates: what `openswarm new` can start from.
#include <algorithm>

#include <nlohmann/json.hpp>

#include "../suggest.hpp"
#include "../templates.hpp"
#include "commands.hpp"

namespace openswarm {

void add_templates_command(CLI::App &app, const Paths &paths) {
    auto json = std::make_shared<bool>(false);
    CLI::App *cmd = app.add_subcommand("templates", "List the app templates");
    cmd->add_flag("--json", *json, "print them as JSON");
    cmd->callback([json, &paths] {
        auto all = list_templates(paths.templates());
        if (*json) {
            nlohmann::json out = nlohmann::json::array();
            for (const auto &t : all)
                out.push_back({{"name", t.name}, {"description", t.description}, {"ports", t.ports}});
            std::printf("%s\n", out.dump(2).c_str());
        } else {
            int width = 0; // the longest name: descriptions line up in one column
            for (const auto &t : all) width = std::max(width, static_cast<int>(t.name.size()));
            for (const auto &t : all)
                std::printf("%-*s  %s [%s]\n", width, t.name.c_str(), t.description.c_str(),
                            join(t.ports).c_str());
        }
        exit_code = EXIT_OK;
    });
}

}  // namespace openswarm
