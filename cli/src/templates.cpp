#include "templates.hpp"

#include <algorithm>
#include <fstream>

#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

namespace openswarm {

std::vector<TemplateInfo> list_templates(const fs::path &templates_dir) {
    std::vector<TemplateInfo> out;
    for (const auto &entry : fs::directory_iterator(templates_dir)) {
        fs::path meta = entry.path() / "template.json";
        if (!entry.is_directory() || !fs::exists(meta)) continue;
        std::ifstream in(meta);
        auto doc = nlohmann::json::parse(in);
        TemplateInfo t;
        t.name = entry.path().filename().string();
        t.description = doc.value("description", "");
        t.ports = doc.value("ports", std::vector<std::string>{});
        t.dir = entry.path();
        out.push_back(t);
    }
    std::sort(out.begin(), out.end(),
              [](const TemplateInfo &a, const TemplateInfo &b) { return a.name < b.name; });
    return out;
}

}  // namespace openswarm
