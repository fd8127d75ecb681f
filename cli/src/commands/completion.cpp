// openswarm completion bash|zsh: a completion script made from the
// command-line definitions themselves (CLI11's tree of subcommands and
// options), so it never lists a command the tool lacks or misses one.
#include <string>
#include <vector>

#include "commands.hpp"

namespace openswarm {

namespace {

// One command's path ("config check"; "" for the tool) and the words that
// may follow it: its subcommands and option names.
struct Completions {
    std::string path;
    std::vector<std::string> words;
};

void collect(const CLI::App &command, const std::string &path, std::vector<Completions> &out) {
    Completions here{path, {}};
    for (const CLI::App *sub : command.get_subcommands({})) here.words.push_back(sub->get_name());
    for (const CLI::Option *option : command.get_options()) {
        for (const auto &name : option->get_snames()) here.words.push_back("-" + name);
        for (const auto &name : option->get_lnames()) here.words.push_back("--" + name);
    }
    out.push_back(here);
    for (const CLI::App *sub : command.get_subcommands({}))
        collect(*sub, path.empty() ? sub->get_name() : path + " " + sub->get_name(), out);
}

std::string words_of(const std::vector<std::string> &words) {
    std::string s;
    for (const auto &w : words) s += (s.empty() ? "" : " ") + w;
    return s;
}

// The bash function: the words typed so far that name subcommands give
// the path; the path's words are offered; files otherwise (-o default).
std::string bash_function(const CLI::App &app) {
    std::vector<Completions> all;
    collect(app, "", all);
    std::string paths, cases;
    for (const auto &c : all) {
        if (!c.path.empty()) paths += std::string(paths.empty() ? "" : "|") + "\"" + c.path + "\"";
        cases += "    \"" + c.path + "\") words=\"" + words_of(c.words) + "\" ;;\n";
    }
    return "_openswarm() {\n"
           "  local cur=${COMP_WORDS[COMP_CWORD]} path=\"\" words=\"\" i next\n"
           "  for ((i = 1; i < COMP_CWORD; i++)); do\n"
           "    next=\"${path:+$path }${COMP_WORDS[i]}\"\n"
           "    case \"$next\" in\n"
           "      " + paths + ") path=$next ;;\n"
           "    esac\n"
           "  done\n"
           "  case \"$path\" in\n" + cases +
           "  esac\n"
           "  COMPREPLY=($(compgen -W \"$words\" -- \"$cur\"))\n"
           "}\n";
}

int print_script(const CLI::App &app, const std::string &shell) {
    std::string script = bash_function(app);
    if (shell == "bash") {
        std::printf("# bash completion for openswarm, made by `openswarm completion bash`:\n"
                    "#   source <(openswarm completion bash)   (or save it in\n"
                    "#   ~/.local/share/bash-completion/completions/openswarm)\n%s"
                    "complete -o default -F _openswarm openswarm\n",
                    script.c_str());
    } else {
        // zsh runs the bash function through its bashcompinit layer.
        std::printf("#compdef openswarm\n# zsh completion for openswarm, made by `openswarm completion zsh`:\n"
                    "#   source <(openswarm completion zsh)   (after compinit, in ~/.zshrc)\n"
                    "autoload -U +X bashcompinit && bashcompinit\n%s"
                    "complete -o default -F _openswarm openswarm\n",
                    script.c_str());
    }
    return EXIT_OK;
}

}  // namespace

void add_completion_command(CLI::App &app, const Paths &) {
    auto shell = std::make_shared<std::string>();
    CLI::App *cmd = app.add_subcommand("completion", "Print the shell completion script (bash or zsh)");
    cmd->add_option("shell", *shell, "bash or zsh")->required()->check(CLI::IsMember({"bash", "zsh"}));
    cmd->footer("bash: source <(openswarm completion bash) in ~/.bashrc\n"
                "zsh:  source <(openswarm completion zsh) in ~/.zshrc, after compinit");
    cmd->callback([&app, shell] { exit_code = print_script(app, *shell); });
}

}  // namespace openswarm
