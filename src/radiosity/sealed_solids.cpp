#include <radiosity/sealed_solids.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <tuple>

namespace rayrad::radiosity {

namespace {
/// Polygons joined through their shared edges (union–find).
struct Components {
    std::vector<size_t> parent;
    explicit Components(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), size_t(0)); }
    size_t find(size_t a) {
        while (parent[a] != a) a = parent[a] = parent[parent[a]];
        return a;
    }
    void join(size_t a, size_t b) { parent[find(a)] = find(b); }
};
}  // namespace

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
    // Every diffuse polygon (emitters too), and per undirected edge the polygons on it and
    // how often it is used each way.
    struct Polygon {
        size_t group;
        std::vector<uint32_t> v;
        Vec3 lo{1e300}, hi{-1e300};  ///< bounds, m
    };
    std::vector<Polygon> polygons;
    for (size_t g = 0; g < scene.groups.size(); ++g) {
        const scene::SurfaceGroup& group = scene.groups[g];
        if (!scene.materials[group.material].isDiffuse()) continue;
        for (const auto& poly : group.polygons) {
            Polygon p{g, {}};
            for (uint32_t i : poly) {
                p.v.push_back(vertexOf(group.positions[i]));
                p.lo = glm::min(p.lo, group.positions[i]), p.hi = glm::max(p.hi, group.positions[i]);
            }
            polygons.push_back(std::move(p));
        }
    }
    struct EdgeUse {
        int forward = 0, backward = 0;  ///< uses from the lower vertex index to the higher, and back
        size_t polygon = 0;             ///< one polygon on it
    };
    std::map<std::pair<uint32_t, uint32_t>, EdgeUse> edges;
    Components components(polygons.size());
    for (size_t k = 0; k < polygons.size(); ++k) {
        const auto& v = polygons[k].v;
        for (size_t i = 0; i < v.size(); ++i) {
            const uint32_t a = v[i], b = v[(i + 1) % v.size()];
            if (a == b) continue;
            auto [it, added] = edges.try_emplace({std::min(a, b), std::max(a, b)});
            (a < b ? it->second.forward : it->second.backward) += 1;
            if (added) it->second.polygon = k;
            else components.join(k, it->second.polygon);
        }
    }
    // A component is closed when each of its edges is used once each way.
    std::vector<char> closed(polygons.size(), 1);  // per component root
    for (const auto& [edge, use] : edges)
        if (use.forward != 1 || use.backward != 1) closed[components.find(use.polygon)] = 0;
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
        if (scene.materials[group.material].isEmissive()) sources.insert(sources.end(), group.positions.begin(), group.positions.end());
    const double margin = 1e-6 * scene.diagonal();
    for (size_t root = 0; root < polygons.size(); ++root) {
        if (!closed[root] || components.find(root) != root) continue;
        for (const Vec3& s : sources)
            if (glm::all(glm::greaterThanEqual(s, lo[root] - margin)) && glm::all(glm::lessThanEqual(s, hi[root] + margin))) {
                closed[root] = 0;
                break;
            }
    }
    // A group is sealed when every one of its polygons is in a sealed component.
    std::vector<char> sealed(scene.groups.size(), 0);
    std::vector<char> seen(scene.groups.size(), 0);
    for (size_t k = 0; k < polygons.size(); ++k) {
        const size_t g = polygons[k].group;
        const bool in = closed[components.find(k)] != 0;
        sealed[g] = seen[g] ? (sealed[g] && in) : in;
        seen[g] = 1;
    }
    return sealed;
}

}  // namespace rayrad::radiosity
