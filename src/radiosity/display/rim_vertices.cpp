#include <radiosity/display/rim_vertices.h>

#include <radiosity/mesh/covered_patches.h>
#include <radiosity/mesh/mesh_location.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace rayrad::radiosity {

std::vector<GatherPoint> rimVertices(const PatchMesh& mesh, const Visibility& vis, const std::vector<int64_t>& patchOf,
                                     const std::vector<char>& taken, double minDiameter, double nudge, double lift) {
    std::vector<GatherPoint> points;
    if (mesh.covered.empty()) return points;
    std::vector<std::vector<uint32_t>> around(mesh.vertices.size());
    for (uint32_t i = 0; i < mesh.patches.size(); ++i)
        for (uint32_t v : mesh.patches[i].v) around[v].push_back(i);
    // The covered patches at the rim (a corner shared with an open patch): their corners'
    // values reach the visible part of the patches around the rim.
    std::vector<char> hasOpen(mesh.vertices.size(), 0), atRim(mesh.vertices.size(), 0);
    for (uint32_t i = 0; i < mesh.patches.size(); ++i)
        if (!mesh.covered[i])
            for (uint32_t v : mesh.patches[i].v) hasOpen[v] = 1;
    for (uint32_t i = 0; i < mesh.patches.size(); ++i) {
        const Patch& p = mesh.patches[i];
        if (mesh.covered[i] && p.diameter >= minDiameter && (hasOpen[p.v[0]] || hasOpen[p.v[1]] || hasOpen[p.v[2]]))
            for (uint32_t v : p.v) atRim[v] = 1;
    }
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
        const auto& ps = around[v];
        if (!atRim[v] || taken[v] || patchOf[v] < 0) continue;
        const Patch& own = mesh.patches[patchOf[v]];
        const Vec3& x = mesh.vertices[v];
        const double reach = kCoverDiameters * own.diameter;  // as coveredPatches looks
        if (!coveredAt(vis, x, own.normal, reach, lift)) {
            points.push_back({v, nudgeInside(mesh, static_cast<size_t>(patchOf[v]), x, nudge), own.normal});
            continue;
        }
        // Under the cover: the nearest open point of its patches on the same plane.
        const auto [t1, t2] = tangentFrame(own.normal);
        std::optional<Vec3> open;
        for (int ring = 1; ring <= 8 && !open; ++ring)
            for (int k = 0; k < 16 && !open; ++k) {
                const double phi = 2 * kPi * k / 16;
                const Vec3 y = x + ring * own.diameter / 8 * (std::cos(phi) * t1 + std::sin(phi) * t2);
                const bool onSurface = std::any_of(ps.begin(), ps.end(), [&](uint32_t i) {
                    const Patch& p = mesh.patches[i];
                    if (!(p.area > 0) || glm::dot(p.normal, own.normal) <= 1 - 1e-9) return false;
                    const Vec3 b = barycentric(mesh.corner(p, 0), mesh.corner(p, 1), mesh.corner(p, 2), y);
                    return std::min({b[0], b[1], b[2]}) >= 0;
                });
                if (onSurface && !coveredAt(vis, y, own.normal, reach, lift)) open = y;
            }
        if (open) points.push_back({v, *open, own.normal});
    }
    return points;
}

}  // namespace rayrad::radiosity
