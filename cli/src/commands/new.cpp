// openswarm new NAME --template T --port P: scaffold an app folder.
#include <fstream>
#include <sstream>

#include "../app_config.hpp"
#include "../json_checks.hpp"
#include "../names.hpp"
#include "../ports.hpp"
#include "../suggest.hpp"
#include "../templates.hpp"
#include "commands.hpp"

namespace fs = std::filesystem;

namespace openswarm {

namespace {

struct NewOptions {
    std::string name;
    std::string template_name = "blinky";
    std::string port; // empty: the template's first (kilobot for most)
    std::string parent = ".";
    bool force = false;
};

std::string substitute(std::string text, const NewOptions &o) {
    for (const auto &[key, value] : {std::pair<std::string, std::string>{"{{name}}", o.name},
                                     {"{{port}}", o.port}}) {
        for (size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + value.size()))
            text.replace(at, key.size(), value);
    }
    return text;
}

// Copy the template into dir (a fresh, empty folder).
void copy_template(const TemplateInfo &t, const fs::path &dir, const NewOptions &o) {
    for (const auto &entry : fs::recursive_directory_iterator(t.dir)) {
        fs::path relative = fs::relative(entry.path(), t.dir);
        if (relative == "template.json") continue;
        if (entry.is_directory()) {
            fs::create_directories(dir / relative);
            continue;
        }
        std::ifstream in(entry.path(), std::ios::binary);
        std::stringstream content;
        content << in.rdbuf();
        std::ofstream out(dir / relative, std::ios::binary);
        out << substitute(content.str(), o);
        if (!out) throw std::runtime_error("cannot write " + (dir / relative).string());
    }
}

const TemplateInfo *find_template(const std::vector<TemplateInfo> &all, const std::string &name) {
    for (const auto &t : all)
        if (t.name == name) return &t;
    return nullptr;
}

// Where an app that --force replaces is kept: NAME.replaced-1, -2, ...,
// the first not taken (an app's name holds no '.', so none is an app's).
// Never removed by the tool: every earlier copy stays whole.
fs::path backup_for(const NewOptions &o) {
    std::error_code ec;
    for (int n = 1;; n++) {
        fs::path p = fs::path(o.parent) / (o.name + ".replaced-" + std::to_string(n));
        if (!fs::exists(fs::symlink_status(p, ec))) return p;
    }
}

// Build the app beside its final place and move it in at the end, so a
// failure leaves nothing half-made; an app it replaces (--force) is renamed
// aside whole, and kept (issue 30: it was removed, and an older copy
// deleted without a word; a file that could not be removed left it half).
int place_app(const TemplateInfo &t, const NewOptions &o, const fs::path &dir) {
    fs::path staging = fs::path(o.parent) / ("." + o.name + ".openswarm-new");
    std::error_code ec;
    fs::remove_all(staging, ec);
    try {
        fs::create_directory(staging);
        copy_template(t, staging, o);
    } catch (const std::exception &e) {
        fs::remove_all(staging, ec);
        report(std::string("could not create ") + dir.string() + ": " + e.what() +
               "; check that the folder is writable");
        return EXIT_FAILED;
    }
    bool replacing = fs::exists(fs::symlink_status(dir, ec));
    fs::path old = replacing ? backup_for(o) : fs::path();
    if (replacing) {
        fs::rename(dir, old, ec);
        if (ec) {
            fs::remove_all(staging, ec);
            report("could not move " + dir.string() + " aside to " + old.string() + " (" + ec.message() +
                   "); it is as it was: move it away yourself, or create the app under another name");
            return EXIT_FAILED;
        }
    }
    fs::rename(staging, dir, ec);
    if (ec) {
        std::error_code back;
        if (replacing) fs::rename(old, dir, back);
        fs::remove_all(staging, back);
        report("could not create " + dir.string() + " (" + ec.message() + ")" +
               (replacing ? "; the old app is back in place" : "") + "; check that the folder is writable");
        return EXIT_FAILED;
    }
    // A port nothing here runs is built, then flashed to the robot.
    Runner runner = port_info(o.port).runner;
    const char *next = runner == Runner::none    ? ""
                       : runner == Runner::world ? " && openswarm run --world WORLD.json"
                                                 : " && openswarm run";
    std::printf("Created %s from template '%s' for %s.\nNext: cd %s && openswarm build%s\n",
                dir.string().c_str(), t.name.c_str(), o.port.c_str(), dir.string().c_str(), next);
    if (replacing)
        std::printf("The app it replaces is kept, whole, in %s: remove that folder once you no longer "
                    "need it.\n",
                    old.string().c_str());
    return EXIT_OK;
}

int run_new(NewOptions o, const Paths &paths) {
    if (!is_app_name(o.name)) {
        report(quoted_start(o.name) + " is not a usable app name: use letters, digits, - and _ (starting with a "
               "letter, at most " + std::to_string(app_name_max) + " characters), e.g. `openswarm new my-robot`");
        return EXIT_USAGE;
    }
    if (!taken_app_name(o.name).empty()) {
        report("\"" + o.name + "\" cannot name an app: " + taken_app_name(o.name) + "; choose another name");
        return EXIT_USAGE;
    }
    auto all = list_templates(paths.templates());
    std::vector<std::string> names;
    for (const auto &t : all) names.push_back(t.name);
    const TemplateInfo *t = find_template(all, o.template_name);
    if (t == nullptr) {
        report("unknown template '" + o.template_name + "'; templates: " + join(names) +
               did_you_mean(o.template_name, names, '\'') +
               "; `openswarm templates` describes them");
        return EXIT_USAGE;
    }
    if (o.port.empty() && !t->ports.empty()) o.port = t->ports.front();
    if (!is_port(o.port)) {
        report(unknown_port_message(o.port));
        return EXIT_USAGE;
    }
    if (std::find(t->ports.begin(), t->ports.end(), o.port) == t->ports.end()) {
        report("template '" + t->name + "' does not build for port '" + o.port +
               "'; it builds for: " + join(t->ports));
        return EXIT_USAGE;
    }
    std::error_code ec;
    if (!fs::is_directory(o.parent, ec)) {
        report("-C " + o.parent + ": no such folder; create it first (mkdir -p " + o.parent +
               "), or leave -C out to create the app here");
        return EXIT_USAGE;
    }
    fs::path dir = fs::path(o.parent) / o.name;
    if (fs::exists(dir) && !o.force) {
        report(dir.string() + " already exists; pick another name, or pass --force to replace it");
        return EXIT_USAGE;
    }
    return place_app(*t, o, dir);
}

}  // namespace

void add_new_command(CLI::App &app, const Paths &paths) {
    auto o = std::make_shared<NewOptions>();
    CLI::App *cmd = app.add_subcommand("new", "Create an app folder from a template");
    cmd->add_option("name", o->name, "the app's name (and folder)")->required();
    cmd->add_option("-t,--template", o->template_name, "template to start from (openswarm templates)")
        ->capture_default_str();
    cmd->add_option("-p,--port", o->port,
                    "robot to build for (openswarm ports; default: the template's first, kilobot for "
                    "most)");
    cmd->add_option("-C,--directory", o->parent, "where to create the folder")->capture_default_str();
    cmd->add_flag("-f,--force", o->force,
                  "replace an existing folder of that name (it is kept, renamed NAME.replaced-1, -2, ...)");
    cmd->callback([o, &paths] { exit_code = run_new(*o, paths); });
}

}  // namespace openswarm
