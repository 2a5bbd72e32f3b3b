// Pipeline options for tests: no progress output, the given --set overrides.
#pragma once

#include <app/pipeline.h>

#include <fmt/format.h>
#include <string>

#include <vector>

namespace rayrad::test {

inline app::PipelineOptions quiet(std::vector<scene::Override> overrides = {}) {
    app::PipelineOptions p;
    p.quiet = true;
    p.overrides = std::move(overrides);
    return p;
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
