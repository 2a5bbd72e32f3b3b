#include <app/coincident_surfaces.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <unordered_map>
#include <vector>

namespace rayrad::app {

namespace {

/// Coincident area below this share of the scene's is left unsaid.
constexpr double kMinShare = 1e-3;

/// A plane, quantised: the unit normal to 1/1000, the offset n·x to `tolerance` m.
using PlaneKey = std::tuple<int, int, int, int64_t>;

/// The 2D coordinates of x in the plane with normal n: the two axes other than n's largest.
glm::dvec2 inPlane(const Vec3& x, const Vec3& n) {
    const int drop = longestAxis(glm::abs(n));
    return drop == 0 ? glm::dvec2(x.y, x.z) : drop == 1 ? glm::dvec2(x.z, x.x) : glm::dvec2(x.x, x.y);
}

}  // namespace

std::optional<std::string> coincidentSurfacesWarning(const scene::Scene& scene, const radiosity::PatchMesh& mesh) {
    const double tolerance = std::max(1e-6, 1e-5 * scene.diagonal());  // m: "the same plane"
    auto keyOf = [&](const radiosity::Patch& p, int64_t shift) {
        const Vec3 n = p.normal;
        return PlaneKey{static_cast<int>(std::lround(1000 * n.x)), static_cast<int>(std::lround(1000 * n.y)),
                        static_cast<int>(std::lround(1000 * n.z)),
                        static_cast<int64_t>(std::llround(glm::dot(n, p.centroid) / tolerance)) + shift};
    };
    // Each plane's patches, in a 2D grid of cells as wide as the plane's largest patch, so a
    // centroid is tested against the patches of its own and the next cells only.
    struct Plane {
        std::vector<uint32_t> patches;
        double cell = 0;
        bool severalGroups = false;
        std::unordered_map<int64_t, std::vector<uint32_t>> grid;
    };
    std::map<PlaneKey, Plane> planes;
    for (uint32_t i = 0; i < mesh.patches.size(); ++i) {
        Plane& plane = planes[keyOf(mesh.patches[i], 0)];
        const radiosity::Patch& p = mesh.patches[i];
        if (!plane.patches.empty() && mesh.patches[plane.patches.front()].group != p.group) plane.severalGroups = true;
        plane.patches.push_back(i);
        plane.cell = std::max(plane.cell, p.diameter);
    }
    auto cellOf = [](const glm::dvec2& x, double size, int dx, int dy) {
        const int64_t u = static_cast<int64_t>(std::floor(x.x / size)) + dx, v = static_cast<int64_t>(std::floor(x.y / size)) + dy;
        return u * 73856093 ^ v * 19349663;
    };
    for (auto& [key, plane] : planes)
        for (uint32_t j : plane.patches) {
            const radiosity::Patch& q = mesh.patches[j];
            plane.grid[cellOf(inPlane(q.centroid, q.normal), plane.cell, 0, 0)].push_back(j);
        }

    std::map<std::pair<int, int>, double> shared;  // (group, group) → m² of the one lying on the other
    for (uint32_t i = 0; i < mesh.patches.size(); ++i) {
        const radiosity::Patch& p = mesh.patches[i];
        const glm::dvec2 c = inPlane(p.centroid, p.normal);
        bool found = false;
        for (int64_t shift = -1; shift <= 1 && !found; ++shift) {
            auto it = planes.find(keyOf(p, shift));
            if (it == planes.end()) continue;
            const Plane& plane = it->second;
            if (shift == 0 && !plane.severalGroups) continue;  // one surface's own plane
            for (int dx = -1; dx <= 1 && !found; ++dx)
                for (int dy = -1; dy <= 1 && !found; ++dy) {
                    auto cell = plane.grid.find(cellOf(c, plane.cell, dx, dy));
                    if (cell == plane.grid.end()) continue;
                    for (uint32_t j : cell->second) {
                        const radiosity::Patch& q = mesh.patches[j];
                        if (q.group == p.group || glm::length(q.centroid - p.centroid) > q.diameter) continue;
                        // p's centroid on q (the same plane): every barycentric weight ≥ 0 (an edge counts).
                        const Vec3 w = barycentric(mesh.corner(q, 0), mesh.corner(q, 1), mesh.corner(q, 2), p.centroid);
                        if (!(std::min({w.x, w.y, w.z}) >= -1e-9)) continue;
                        shared[{std::min(p.group, q.group), std::max(p.group, q.group)}] += p.area;
                        found = true;
                        break;
                    }
                }
        }
    }
    if (shared.empty()) return std::nullopt;
    double total = 0, area = 0;
    for (const auto& p : mesh.patches) area += p.area;
    auto worst = shared.begin();
    for (auto it = shared.begin(); it != shared.end(); ++it) {
        total += it->second;
        if (it->second > worst->second) worst = it;
    }
    // Slivers where modelled parts overlap by a hair are not worth a word.
    if (0.5 * total < kMinShare * area) return std::nullopt;
    auto name = [&](int g) {
        return fmt::format("{} (material \"{}\")", scene.groups[g].where, scene.materials[scene.groups[g].material].name);
    };
    const auto& [a, b] = worst->first;
    return fmt::format("{} and {}: {:.3g} m² of them lie in one plane, facing the same way ({:.3g} m² of coincident "
                       "surfaces in all, {} pair(s)): both receive the light there and both reflect it, so the scene "
                       "holds more light than its lamps give. Is a surface modelled twice?",
                       name(a), name(b), 0.5 * worst->second, 0.5 * total, shared.size());
}

}  // namespace rayrad::app
