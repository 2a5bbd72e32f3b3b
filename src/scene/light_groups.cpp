#include <scene/light_groups.h>

#include <algorithm>

namespace rayrad::scene {

std::vector<std::string> lightGroups(const Scene& scene) {
    std::vector<std::string> named;
    bool ungrouped = false;
    auto note = [&](const std::string& g) {
        if (g.empty()) ungrouped = true;
        else if (std::find(named.begin(), named.end(), g) == named.end()) named.push_back(g);
    };
    for (const auto& l : scene.lights) note(l.lightGroup);
    for (const auto& m : scene.materials)
        if (m.isEmissive()) note(m.lightGroup);
    if (named.empty()) return {};
    if (ungrouped) named.insert(named.begin(), "");
    return named;
}

void keepLightGroup(Scene& scene, const std::string& group) {
    scene.lights.erase(std::remove_if(scene.lights.begin(), scene.lights.end(),
                                      [&](const PointLight& l) { return l.lightGroup != group; }),
                       scene.lights.end());
    for (auto& m : scene.materials)
        if (m.isEmissive() && m.lightGroup != group) m.emission = Rgb(0.0);
}

void removeElectricLight(Scene& scene) {
    scene.lights.clear();
    for (auto& m : scene.materials)
        if (m.isEmissive()) m.emission = Rgb(0.0);
}

}  // namespace rayrad::scene
