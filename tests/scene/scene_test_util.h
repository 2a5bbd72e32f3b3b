// Parsing helpers for the scene tests: collect errors instead of throwing.
#pragma once

#include <scene/scene_parser.h>

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
inline std::string boxScene(const std::string& material = R"({"type": "diffuse", "reflectance": 0.5})",
                            const std::string& light = R"({"type": "point", "position": [0.5, 0.5, 0.5], "intensity_cd": 100})") {
    return R"({"materials": {"grey": )" + material + R"(},
               "objects": [{"type": "box", "min": [0,0,0], "max": [1,1,1], "facing": "inward", "material": "grey"}],
               "lights": [)" + light + "]}";
}

}  // namespace rayrad::test
