#include <app/annual/opening_samples.h>

#include <scene/polygon.h>

#include <algorithm>
#include <cmath>

namespace rayrad::app {

std::vector<OpeningSamples> openingSamples(const scene::Scene& scene, int perSide) {
    std::vector<OpeningSamples> out;
    for (const auto& g : scene.groups) {
        const auto& mat = scene.materials[g.material];
        if (!mat.isOpening()) continue;
        for (const auto& poly : g.polygons) {
            std::vector<Vec3> v;
            for (uint32_t i : poly) v.push_back(g.positions[i]);
            OpeningSamples o;
            o.out = -scene::polygonNormal(v);  // an opening's front faces the room
            o.transmittance = mat.transmittance;
            o.area = scene::polygonArea(v);
            const auto triangles = scene::triangulate(v);
            for (const auto& t : triangles) {
                const double area = 0.5 * glm::length(glm::cross(v[t[1]] - v[t[0]], v[t[2]] - v[t[0]]));
                const double share = o.area > 0 ? area / o.area : 0.0;
                const int n = std::max(1, static_cast<int>(std::lround(perSide * std::sqrt(share * triangles.size()))));
                // The n × n cells of the unit square onto the triangle, equal areas to equal
                // areas: (1 − √u) A + √u (1 − w) B + √u w C.
                for (int a = 0; a < n; ++a)
                    for (int b = 0; b < n; ++b) {
                        const double su = std::sqrt((a + 0.5) / n), w = (b + 0.5) / n;
                        o.points.push_back((1 - su) * v[t[0]] + su * (1 - w) * v[t[1]] + su * w * v[t[2]]);
                        o.pointArea.push_back(area / (n * n));
                    }
            }
            out.push_back(std::move(o));
        }
    }
    return out;
}

std::unique_ptr<radiosity::DirectLight> openingGlazings(const scene::Scene& s) {
    // The openings alone (no other surface, lamp or mirror), seen from the whole scene.
    scene::Scene copy;
    copy.file = s.file;
    copy.materials = s.materials;
    copy.boundsMin = s.boundsMin, copy.boundsMax = s.boundsMax;
    for (const auto& g : s.groups)
        if (s.materials[g.material].isOpening()) copy.groups.push_back(g);
    scene::Daylight d = *s.daylight;
    d.channel.reset();
    d.sun.reset();
    d.sunNormalIlluminance = 0;
    d.perez.reset();
    d.kind = scene::SkyKind::Uniform;
    scene::finishDaylight(d, 1.0, 0.0);
    copy.daylight = std::move(d);
    return std::make_unique<radiosity::DirectLight>(copy);
}

}  // namespace rayrad::app
