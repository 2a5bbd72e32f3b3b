#include <radiosity/direct/sealed_solids.h>

#include <core/disjoint_sets.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace rayrad::radiosity {

std::vector<char> sealedGroups(const scene::Scene& scene) {
    // Vertices welded by position: a box's faces are groups of their own, with the same
    // corner positions (a position within 10⁻⁹ of the diagonal of another on the same grid
    // point is the same vertex; one a hair across a grid line is not, and its solid counts
    // as open).
    const double cell = 1e-9 * std::max(scene.diagonal(), 1e-300);
    using Key = std::tuple<int64_t, int64_t, int64_t>;
    std::map<Key, uint32_t> vertexAt;
    auto vertexOf = [&](const Vec3& p) {
        const Key key{std::llround(p.x / cell), std::llround(p.y / cell), std::llround(p.z / cell)};
        return vertexAt.emplace(key, static_cast<uint32_t>(vertexAt.size())).first->second;
    };
    // Every diffuse polygon (emitters too) as its bounds and its directed edges.
    struct Polygon {
        size_t group;
        Vec3 lo{1e300}, hi{-1e300};  ///< bounds, m
    };
    struct HalfEdge {
        uint32_t low, high;  ///< its welded vertices, the lower index first
        bool forward;        ///< runs from `low` to `high`
        uint32_t polygon;
    };
    std::vector<Polygon> polygons;
    std::vector<HalfEdge> halfEdges;
    std::vector<uint32_t> welded;  // one polygon's vertices
    for (size_t g = 0; g < scene.groups.size(); ++g) {
        const scene::SurfaceGroup& group = scene.groups[g];
        if (!scene.materials[group.material].isDiffuse()) continue;
        for (const auto& poly : group.polygons) {
            Polygon p{g};
            const auto k = static_cast<uint32_t>(polygons.size());
            welded.clear();
            for (uint32_t i : poly) {
                p.lo = glm::min(p.lo, group.positions[i]), p.hi = glm::max(p.hi, group.positions[i]);
                welded.push_back(vertexOf(group.positions[i]));
            }
            for (size_t i = 0; i < welded.size(); ++i) {
                const uint32_t a = welded[i], b = welded[(i + 1) % welded.size()];
                if (a != b) halfEdges.push_back({std::min(a, b), std::max(a, b), a < b, k});
            }
            polygons.push_back(p);
        }
    }
    // The polygons on one edge are joined; a component is closed when each of its edges is
    // used exactly once each way.
    std::sort(halfEdges.begin(), halfEdges.end(),
              [](const HalfEdge& x, const HalfEdge& y) { return std::tie(x.low, x.high) < std::tie(y.low, y.high); });
    DisjointSets components(polygons.size());
    std::vector<std::pair<size_t, bool>> edgeClosed;  // per edge: one polygon on it, and whether it closes
    for (size_t i = 0; i < halfEdges.size();) {
        size_t end = i, forward = 0;
        for (; end < halfEdges.size() && halfEdges[end].low == halfEdges[i].low &&
               halfEdges[end].high == halfEdges[i].high;
             ++end) {
            forward += halfEdges[end].forward;
            components.join(halfEdges[end].polygon, halfEdges[i].polygon);
        }
        edgeClosed.push_back({halfEdges[i].polygon, end - i == 2 && forward == 1});
        i = end;
    }
    std::vector<char> closed(polygons.size(), 1);  // per component root
    for (const auto& [polygon, closes] : edgeClosed)
        if (!closes) closed[components.find(polygon)] = 0;
    // Its bounds, and whether a light source lies within them (on the boundary too).
    std::vector<Vec3> lo(polygons.size(), Vec3(1e300)), hi(polygons.size(), Vec3(-1e300));  // per component root
    for (size_t k = 0; k < polygons.size(); ++k) {
        const size_t root = components.find(k);
        lo[root] = glm::min(lo[root], polygons[k].lo), hi[root] = glm::max(hi[root], polygons[k].hi);
    }
    std::vector<Vec3> sources;
    for (const scene::PointLight& l : scene.lights) {
        sources.push_back(l.position);
        sources.insert(sources.end(), l.openingPoints.begin(), l.openingPoints.end());
    }
    for (const scene::SurfaceGroup& group : scene.groups)
        if (scene.materials[group.material].isEmissive())
            sources.insert(sources.end(), group.positions.begin(), group.positions.end());
    const double margin = 1e-6 * scene.diagonal();
    for (size_t root = 0; root < polygons.size(); ++root) {
        if (!closed[root] || components.find(root) != root) continue;
        for (const Vec3& s : sources)
            if (glm::all(glm::greaterThanEqual(s, lo[root] - margin)) &&
                glm::all(glm::lessThanEqual(s, hi[root] + margin))) {
                closed[root] = 0;
                break;
            }
    }
    // A group is sealed when every one of its polygons is in a sealed component.
    std::vector<char> sealed(scene.groups.size(), 0);
    for (const Polygon& p : polygons) sealed[p.group] = 1;
    for (size_t k = 0; k < polygons.size(); ++k)
        if (!closed[components.find(k)]) sealed[polygons[k].group] = 0;
    return sealed;
}

}  // namespace rayrad::radiosity
