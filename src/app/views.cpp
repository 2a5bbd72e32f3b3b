#include <app/views.h>

#include <core/input_error.h>

#include <algorithm>
#include <filesystem>

namespace rayrad::app {

std::vector<std::string> selectViews(const scene::SceneDesc& desc, const std::vector<std::string>& requested) {
    if (desc.views.empty()) throw InputError(placeMessage(desc.file, "/camera", "rendering needs a camera (\"camera\" or \"cameras\")"));
    std::vector<std::string> names;
    for (const auto& [name, unused] : desc.views) names.push_back(name);
    if (requested.empty()) return {names.front()};
    if (std::find(requested.begin(), requested.end(), "all") != requested.end()) return names;
    std::string known;
    for (size_t i = 0; i < names.size(); ++i) known += (i ? ", " : "") + ("\"" + names[i] + "\"");
    for (const auto& r : requested)
        if (std::find(names.begin(), names.end(), r) == names.end())
            throw InputError(placeMessage(desc.file, "--camera", "the scene has no view \"" + r + "\" (it has " + known + ", or all)"));
    std::vector<std::string> out;  // the scene's order, each once
    for (const auto& n : names)
        if (std::find(requested.begin(), requested.end(), n) != requested.end()) out.push_back(n);
    return out;
}

std::string viewPath(const std::string& path, const std::string& view, size_t viewCount) {
    if (viewCount <= 1) return path;
    const std::filesystem::path p(path);
    return (p.parent_path() / (p.stem().string() + "." + view + p.extension().string())).string();
}

}  // namespace rayrad::app
