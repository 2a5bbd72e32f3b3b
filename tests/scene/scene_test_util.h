// Scenes and parsing helpers for the tests: small scenes as JSON, errors collected instead of thrown.
#pragma once

#include <scene/scene_parser.h>

#include <fmt/format.h>

#include <string>
#include <vector>

namespace rayrad::test {

struct ParseErrors {
    std::vector<std::string> messages;  ///< "place: message"
    bool contains(const std::string& s) const {
        for (const auto& m : messages)
            if (m.find(s) != std::string::npos) return true;
        return false;
    }
};

inline ParseErrors parseErrors(const std::string& json, const std::vector<scene::Override>& overrides = {}) {
    ParseErrors e;
    scene::parseScene(json, "test.json", overrides, [&](const std::string& place, const std::string& msg) {
        e.messages.push_back(place + ": " + msg);
    });
    return e;
}

/// A valid minimal scene: a closed box and a point light; `extra` is spliced in.
inline std::string boxScene(
    const std::string& material = R"({"type": "diffuse", "reflectance": 0.5})",
    const std::string& light = R"({"type": "point", "position": [0.5, 0.5, 0.5], "intensity_cd": 100})") {
    return R"({"materials": {"grey": )" + material + R"(},
               "objects": [{"type": "box", "min": [0,0,0], "max": [1,1,1], "facing": "inward", "material": "grey"}],
               "lights": [)" +
           light + "]}";
}

/// A closed diffuse sphere of radius 1 (reflectance rho, seen from inside) with a point
/// light of 100 cd off centre at (0.2, 0.4, 0.6) and sensors A (0, 0, 1), B (0, −1, 0) and
/// C (1, 1, 1)/√3 facing inward; `radiosity` is the body of the "radiosity" object. Every
/// point has E_ind = ρ/(1−ρ) Φ/A (method.md).
inline std::string closedSphereScene(double rho, int subdivisions, const std::string& radiosity) {
    return fmt::format(R"({{"materials": {{"m": {{"reflectance": {}}}}},
        "objects": [{{"type": "sphere", "material": "m", "radius": 1, "subdivisions": {}, "facing": "inward"}}],
        "lights": [{{"type": "point", "position": [0.2, 0.4, 0.6], "intensity_cd": 100}}],
        "sensors": [{{"name": "A", "position": [0, 0, 1], "normal": [0, 0, -1]}},
                    {{"name": "B", "position": [0, -1, 0], "normal": [0, 1, 0]}},
                    {{"name": "C", "position": [0.57735027, 0.57735027, 0.57735027], "normal": [-0.57735027, -0.57735027, -0.57735027]}}],
        "radiosity": {{{}}}}})",
                       rho, subdivisions, radiosity);
}

}  // namespace rayrad::test
