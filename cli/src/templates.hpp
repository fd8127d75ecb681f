// The app templates `openswarm new` scaffolds from (templates/<name>/).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace openswarm {

struct TemplateInfo {
    std::string name;
    std::string description;
    std::vector<std::string> ports;
    std::filesystem::path dir;
};

std::vector<TemplateInfo> list_templates(const std::filesystem::path &templates_dir);

}  // namespace openswarm
