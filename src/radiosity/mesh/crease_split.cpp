#include <radiosity/mesh/crease_split.h>

#include <core/disjoint_sets.h>

#include <cmath>

namespace rayrad::radiosity {

size_t splitAtCreases(std::vector<Vec3>& positions, std::vector<std::array<uint32_t, 3>>& triangles,
                      double creaseAngleDeg) {
    if (!(creaseAngleDeg > 0)) return 0;
    const double cosCrease = std::cos(glm::radians(creaseAngleDeg));
    std::vector<Vec3> normal(triangles.size());
    for (size_t t = 0; t < triangles.size(); ++t) {
        const auto& c = triangles[t];
        const Vec3 n = glm::cross(positions[c[1]] - positions[c[0]], positions[c[2]] - positions[c[0]]);
        const double len = glm::length(n);
        normal[t] = len > 0 ? n / len : Vec3(0.0);  // a degenerate triangle joins any side
    }
    std::vector<std::vector<uint32_t>> around(positions.size());  // vertex → its triangles
    for (size_t t = 0; t < triangles.size(); ++t)
        for (uint32_t v : triangles[t]) around[v].push_back(static_cast<uint32_t>(t));

    const size_t before = positions.size();
    for (size_t v = 0; v < before; ++v) {
        const auto& tris = around[v];
        if (tris.size() < 2) continue;
        DisjointSets sides(tris.size());
        // Triangles a and b share an edge through v when they share a second vertex.
        auto otherCorners = [&](uint32_t t) {
            std::array<uint32_t, 2> o{};
            int k = 0;
            for (uint32_t w : triangles[t])
                if (w != v && k < 2) o[k++] = w;
            return o;
        };
        for (size_t a = 0; a < tris.size(); ++a)
            for (size_t b = a + 1; b < tris.size(); ++b) {
                const auto oa = otherCorners(tris[a]), ob = otherCorners(tris[b]);
                const bool shareEdge = oa[0] == ob[0] || oa[0] == ob[1] || oa[1] == ob[0] || oa[1] == ob[1];
                const Vec3 &na = normal[tris[a]], &nb = normal[tris[b]];
                const bool smooth = glm::dot(na, na) == 0 || glm::dot(nb, nb) == 0 || glm::dot(na, nb) >= cosCrease;
                if (shareEdge && smooth) sides.join(a, b);
            }
        // The first side keeps v; every other side gets a copy.
        std::vector<std::pair<size_t, uint32_t>> copyOf;  // side root → its vertex
        const size_t first = sides.find(0);
        for (size_t a = 0; a < tris.size(); ++a) {
            const size_t root = sides.find(a);
            if (root == first) continue;
            uint32_t id = 0;
            bool found = false;
            for (const auto& [r, i] : copyOf)
                if (r == root) id = i, found = true;
            if (!found) {
                id = static_cast<uint32_t>(positions.size());
                positions.push_back(positions[v]);
                copyOf.push_back({root, id});
            }
            for (uint32_t& w : triangles[tris[a]])
                if (w == v) w = id;
        }
    }
    return positions.size() - before;
}

}  // namespace rayrad::radiosity
