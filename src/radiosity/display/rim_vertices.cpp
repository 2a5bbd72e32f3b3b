#include <radiosity/display/rim_vertices.h>

#include <radiosity/mesh/covered_patches.h>
#include <radiosity/mesh/mesh_location.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace rayrad::radiosity {

namespace {

/// The nearest point to x on the patches `ps` in the plane of `own` that no surface covers
/// within `reach` (coveredAt), looked for on rings of an eighth of own's diameter, up to one
/// diameter out; none when every one is covered.
std::optional<Vec3> nearestOpenPoint(const PatchMesh& mesh, const Visibility& vis, const std::vector<uint32_t>& ps,
                                     const Patch& own, const Vec3& x, double reach, double lift) {
    const auto [t1, t2] = tangentFrame(own.normal);
    for (int ring = 1; ring <= 8; ++ring)
        for (int k = 0; k < 16; ++k) {
            const double phi = 2 * kPi * k / 16;
            const Vec3 y = x + ring * own.diameter / 8 * (std::cos(phi) * t1 + std::sin(phi) * t2);
            const bool onSurface = std::any_of(ps.begin(), ps.end(), [&](uint32_t i) {
                const Patch& p = mesh.patches[i];
                if (!(p.area > 0) || glm::dot(p.normal, own.normal) <= 1 - 1e-9) return false;
                const Vec3 b = barycentric(mesh.corner(p, 0), mesh.corner(p, 1), mesh.corner(p, 2), y);
                return std::min({b[0], b[1], b[2]}) >= 0;
            });
            if (onSurface && !coveredAt(vis, y, own.normal, reach, lift)) return y;
        }
    return std::nullopt;
}

}  // namespace

std::vector<GatherPoint> rimVertices(const PatchMesh& mesh, const Visibility& vis, const std::vector<int64_t>& patchOf,
                                     const std::vector<char>& taken, double minDiameter, double nudge, double lift) {
    std::vector<GatherPoint> points;
    if (mesh.covered.empty()) return points;
    const std::vector<std::vector<uint32_t>> around = patchesAround(mesh);
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
        if (const auto open = nearestOpenPoint(mesh, vis, ps, own, x, reach, lift))
            points.push_back({v, *open, own.normal});
    }
    return points;
}

std::vector<char> openGatherPoints(const PatchMesh& mesh, const Visibility& vis, const std::vector<int64_t>& patchOf,
                                   std::vector<GatherPoint>& points, double lift) {
    std::vector<std::vector<uint32_t>> around;
    std::vector<char> moved(points.size(), 0);
    for (size_t k = 0; k < points.size(); ++k) {
        GatherPoint& g = points[k];
        const int64_t i = patchOf[g.vertex];
        if (i < 0 || mesh.isCovered(static_cast<size_t>(i))) continue;
        const Patch& own = mesh.patches[i];
        const double reach = kCoverDiameters * own.diameter;  // as coveredPatches looks
        if (!coveredAt(vis, g.at, own.normal, reach, lift)) continue;
        if (around.empty()) around = patchesAround(mesh);
        if (const auto open = nearestOpenPoint(mesh, vis, around[g.vertex], own, g.at, reach, lift))
            g.at = *open, moved[k] = 1;
    }
    return moved;
}

}  // namespace rayrad::radiosity
