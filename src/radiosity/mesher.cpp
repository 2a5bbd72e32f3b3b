#include <radiosity/mesher.h>

#include <core/check.h>
#include <scene/polygon.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace rayrad::radiosity {

using scene::SurfaceGroup;

double targetEdge(const scene::Scene& scene, const scene::MeshingOptions& options) {
    return options.maxEdge > 0 ? options.maxEdge : scene.diagonal() / 20.0;
}

namespace {

int cellsFor(double length, double edge) { return std::max(1, static_cast<int>(std::ceil(length / edge - 1e-9))); }

void addPatch(PatchMesh& mesh, uint32_t a, uint32_t b, uint32_t c, int material, int group) {
    Patch p;
    p.v = {a, b, c};
    p.material = material;
    p.group = group;
    computeGeometry(mesh, p);
    if (p.area > 0) mesh.patches.push_back(p);
}

/// Bilinear grid over a (possibly slightly non-planar) convex quad v0 v1 v2 v3.
void meshQuad(PatchMesh& mesh, const std::vector<Vec3>& q, int material, int group,
              const scene::MeshingOptions& options, double edge) {
    double lu = std::max(glm::length(q[1] - q[0]), glm::length(q[2] - q[3]));
    double lv = std::max(glm::length(q[3] - q[0]), glm::length(q[2] - q[1]));
    int nu, nv;
    if (options.trianglesPerSurface > 0) {
        // 2·nu·nv ≈ T with nu/nv ≈ lu/lv.
        double cells = options.trianglesPerSurface / 2.0;
        nu = std::max(1, static_cast<int>(std::lround(std::sqrt(cells * lu / lv))));
        nv = std::max(1, static_cast<int>(std::lround(cells / nu)));
    } else {
        nu = cellsFor(lu, edge);
        nv = cellsFor(lv, edge);
    }
    // Keep cells compact: refine the long direction of thin cells.
    double aspect = options.maxCellAspect;
    nu = std::max(nu, static_cast<int>(std::ceil(lu / (aspect * lv / nv) - 1e-9)));
    nv = std::max(nv, static_cast<int>(std::ceil(lv / (aspect * lu / nu) - 1e-9)));

    auto base = static_cast<uint32_t>(mesh.vertices.size());
    for (int j = 0; j <= nv; ++j)
        for (int i = 0; i <= nu; ++i) {
            double s = static_cast<double>(i) / nu, t = static_cast<double>(j) / nv;
            mesh.vertices.push_back((1 - s) * (1 - t) * q[0] + s * (1 - t) * q[1] + s * t * q[2] + (1 - s) * t * q[3]);
        }
    auto at = [&](int i, int j) { return base + static_cast<uint32_t>(j * (nu + 1) + i); };
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
            uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
            if (((i + j) & 1) == 0) {
                addPatch(mesh, a, b, c, material, group);
                addPatch(mesh, a, c, d, material, group);
            } else {
                addPatch(mesh, a, b, d, material, group);
                addPatch(mesh, b, c, d, material, group);
            }
        }
}

/// Splits every triangle of a group into k² triangles; edge points are created once per
/// input edge (keyed by its sorted end points), so adjacent triangles share them.
void meshTriangles(PatchMesh& mesh, const SurfaceGroup& g, const std::vector<std::array<uint32_t, 3>>& tris,
                   int group, const scene::MeshingOptions& options, double edge) {
    double longest = 0;
    for (const auto& t : tris)
        for (int e = 0; e < 3; ++e)
            longest = std::max(longest, glm::length(g.positions[t[(e + 1) % 3]] - g.positions[t[e]]));
    int k;
    if (options.trianglesPerSurface > 0)
        k = std::max(1, static_cast<int>(std::lround(std::sqrt(double(options.trianglesPerSurface) / tris.size()))));
    else
        k = cellsFor(longest, edge);

    std::map<uint32_t, uint32_t> cornerIds;
    std::map<std::tuple<uint32_t, uint32_t, int>, uint32_t> edgeIds;
    auto corner = [&](uint32_t a) {
        auto it = cornerIds.find(a);
        if (it != cornerIds.end()) return it->second;
        auto id = static_cast<uint32_t>(mesh.vertices.size());
        mesh.vertices.push_back(g.positions[a]);
        cornerIds.emplace(a, id);
        return id;
    };
    auto onEdge = [&](uint32_t a, uint32_t b, int i) {  // point i/k of the way from a to b
        if (i == 0) return corner(a);
        if (i == k) return corner(b);
        if (a > b) std::swap(a, b), i = k - i;
        auto key = std::make_tuple(a, b, i);
        auto it = edgeIds.find(key);
        if (it != edgeIds.end()) return it->second;
        auto id = static_cast<uint32_t>(mesh.vertices.size());
        mesh.vertices.push_back(g.positions[a] + (g.positions[b] - g.positions[a]) * (double(i) / k));
        edgeIds.emplace(key, id);
        return id;
    };
    for (const auto& t : tris) {
        // Lattice point (i, j) with i + j ≤ k: p = A + i/k (B - A) + j/k (C - A).
        std::map<std::pair<int, int>, uint32_t> local;
        auto P = [&](int i, int j) {
            if (j == 0) return onEdge(t[0], t[1], i);
            if (i == 0) return onEdge(t[0], t[2], j);
            if (i + j == k) return onEdge(t[1], t[2], j);
            auto key = std::make_pair(i, j);
            auto it = local.find(key);
            if (it != local.end()) return it->second;
            const Vec3 &A = g.positions[t[0]], &B = g.positions[t[1]], &C = g.positions[t[2]];
            auto id = static_cast<uint32_t>(mesh.vertices.size());
            mesh.vertices.push_back(A + (B - A) * (double(i) / k) + (C - A) * (double(j) / k));
            local.emplace(key, id);
            return id;
        };
        for (int j = 0; j < k; ++j)
            for (int i = 0; i + j < k; ++i) {
                addPatch(mesh, P(i, j), P(i + 1, j), P(i, j + 1), g.material, group);
                if (i + j + 1 < k) addPatch(mesh, P(i + 1, j), P(i + 1, j + 1), P(i, j + 1), g.material, group);
            }
    }
}

}  // namespace

PatchMesh premesh(const scene::Scene& scene, const scene::MeshingOptions& options) {
    PatchMesh mesh;
    double edge = targetEdge(scene, options);
    CHECK(edge > 0);
    for (size_t gi = 0; gi < scene.groups.size(); ++gi) {
        const SurfaceGroup& g = scene.groups[gi];
        int group = static_cast<int>(gi);
        if (!scene.isPatchSurface(g)) continue;  // mirrors and glass: no radiosity patches
        if (g.polygons.size() == 1 && g.polygons[0].size() == 4 && options.premesh) {
            std::vector<Vec3> q;
            for (uint32_t i : g.polygons[0]) q.push_back(g.positions[i]);
            meshQuad(mesh, q, g.material, group, options, edge);
            continue;
        }
        std::vector<std::array<uint32_t, 3>> tris;
        for (const auto& poly : g.polygons) {
            if (poly.size() == 3) {
                tris.push_back({poly[0], poly[1], poly[2]});
                continue;
            }
            std::vector<Vec3> v;
            for (uint32_t i : poly) v.push_back(g.positions[i]);
            for (const auto& t : scene::triangulate(v)) tris.push_back({poly[t[0]], poly[t[1]], poly[t[2]]});
        }
        if (options.premesh) {
            meshTriangles(mesh, g, tris, group, options, edge);
            continue;
        }
        // Premeshing off: the input triangles are the patches, shape as given.
        std::map<uint32_t, uint32_t> ids;
        auto id = [&](uint32_t a) {
            auto [it, added] = ids.emplace(a, static_cast<uint32_t>(mesh.vertices.size()));
            if (added) mesh.vertices.push_back(g.positions[a]);
            return it->second;
        };
        for (const auto& t : tris) addPatch(mesh, id(t[0]), id(t[1]), id(t[2]), g.material, group);
    }
    return mesh;
}

}  // namespace rayrad::radiosity
