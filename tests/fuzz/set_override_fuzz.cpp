// libFuzzer target for --set: each line of the input is one --set argument, applied to a
// small valid scene. A bad override must come back as an InputError; anything else is a
// finding. Built by scripts/fuzz.
#include "fuzz_support.h"

#include <scene/scene.h>
#include <scene/scene_parser.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace {
const char* kScene = R"({"materials": {"white": {"reflectance": 0.5}, "lamp": {"type": "emissive", "luminance_cd_m2": 100}},
 "objects": [{"type": "box", "min": [0,0,0], "max": [1,1,1], "facing": "inward", "material": "white"},
             {"type": "quad", "vertices": [[0.4,0.99,0.4],[0.6,0.99,0.4],[0.6,0.99,0.6],[0.4,0.99,0.6]], "material": "lamp"}],
 "lights": [{"type": "spot", "position": [0.5,0.5,0.5], "look_at": [0.5,0,0.5], "intensity_cd": 10}],
 "sensors": [{"name": "s", "position": [0.5,0,0.5], "normal": [0,1,0]}],
 "sensor_grids": [{"name": "g", "origin": [0.1,0,0.1], "u": [0.8,0,0], "v": [0,0,0.8], "counts": [2,2], "normal": [0,1,0]}],
 "camera": {"position": [0.5,0.5,0.1], "look_at": [0.5,0.5,1], "resolution": [8,8]},
 "radiosity": {"max_edge": 0.5}})";
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
    return rayrad::fuzz::onlyInputErrors([&] {
        std::vector<rayrad::scene::Override> overrides;
        for (std::string line; std::getline(lines, line);) overrides.push_back(rayrad::scene::parseOverride(line));
        rayrad::scene::Scene scene = rayrad::scene::buildScene(rayrad::scene::parseScene(kScene, "fuzz.json", overrides));
        (void)scene;
    });
}
