#include <radiosity/mesh/mesher.h>

#include <core/check.h>
#include <radiosity/mesh/bisection.h>
#include <radiosity/mesh/contact_lines.h>
#include <radiosity/mesh/crease_split.h>
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

int cellsFor(double length, double edge) {
    return std::max(1, static_cast<int>(std::ceil(length / edge - 1e-9)));
}

/// The longer of each pair of opposite sides of a quad v0 v1 v2 v3, m: (u, v).
std::pair<double, double> quadSides(const std::vector<Vec3>& q) {
    return {std::max(glm::length(q[1] - q[0]), glm::length(q[2] - q[3])),
            std::max(glm::length(q[3] - q[0]), glm::length(q[2] - q[1]))};
}

/// Grid cells (n_u, n_v) of a quad before contact lines are added: sides of at most
/// `edge` metres (or about trianglesPerSurface triangles), cells within maxCellAspect.
/// In doubles, so an absurd request is counted rather than overflowing.
std::pair<double, double> quadCells(const std::vector<Vec3>& q, const scene::MeshingOptions& options, double edge) {
    const auto [lu, lv] = quadSides(q);
    double nu, nv;
    if (options.trianglesPerSurface > 0) {
        // 2·nu·nv ≈ T with nu/nv ≈ lu/lv.
        double cells = options.trianglesPerSurface / 2.0;
        nu = std::max(1.0, std::round(std::sqrt(cells * lu / lv)));
        nv = std::max(1.0, std::round(cells / nu));
    } else {
        nu = std::max(1.0, std::ceil(lu / edge - 1e-9));
        nv = std::max(1.0, std::ceil(lv / edge - 1e-9));
    }
    // Keep cells compact: refine the long direction of thin cells.
    double aspect = options.maxCellAspect;
    nu = std::max(nu, std::ceil(lu / (aspect * lv / nv) - 1e-9));
    nv = std::max(nv, std::ceil(lv / (aspect * lu / nu) - 1e-9));
    return {nu, nv};
}

/// With `triangles_per_surface`, every triangle of a group of `triangles` becomes k² lattice
/// triangles: this k.
int latticeFactor(const scene::MeshingOptions& options, size_t triangles) {
    return std::max(1, static_cast<int>(std::lround(std::sqrt(double(options.trianglesPerSurface) / triangles))));
}

/// Triangles a longest-edge bisection to `edge` metres makes of triangle (a, b, c),
/// estimated: the pieces' longest edges end up between edge/2 and edge, so about
/// area / (0.3 edge²) of them, and at least one per `edge` along the longest side.
double bisectedCount(const Vec3& a, const Vec3& b, const Vec3& c, double edge) {
    double area = 0.5 * glm::length(glm::cross(b - a, c - a));
    double longest = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
    return std::max({1.0, area / (0.3 * edge * edge), std::ceil(longest / edge)});
}

using Uv3 = std::array<glm::dvec2, 3>;

/// Adds the triangle unless it has no area; `uv`: its corners' texture coordinates, kept
/// in mesh.cornerUv when the scene has textures (else null).
void addPatch(PatchMesh& mesh, uint32_t a, uint32_t b, uint32_t c, int material, int group, const Uv3* uv = nullptr) {
    Patch p;
    p.v = {a, b, c};
    p.material = material;
    p.group = group;
    computeGeometry(mesh, p);
    if (!(p.area > 0)) return;
    mesh.patches.push_back(p);
    if (uv)
        for (const auto& t : *uv) mesh.cornerUv.emplace_back(t);
}

/// The texture coordinates at p of the triangle `corners` whose corners have `uv`
/// (barycentric interpolation; p on the triangle's plane).
glm::dvec2 uvAt(const std::array<Vec3, 3>& corners, const Uv3& uv, const Vec3& p) {
    const Vec3 e1 = corners[1] - corners[0], e2 = corners[2] - corners[0], d = p - corners[0];
    const double a = glm::dot(e1, e1), b = glm::dot(e1, e2), c = glm::dot(e2, e2);
    const double du = glm::dot(d, e1), dv = glm::dot(d, e2), det = a * c - b * b;
    const double s = det > 0 ? (c * du - b * dv) / det : 0, t = det > 0 ? (a * dv - b * du) / det : 0;
    return (1 - s - t) * uv[0] + s * uv[1] + t * uv[2];
}

/// Grid-line parameters in [0, 1] for one direction of length `length` (m): cells of at
/// most `cell` metres between the contact lines, which become grid lines themselves.
std::vector<double> gridLines(double length, double cell, const std::vector<ContactLine>& contacts) {
    std::vector<double> breaks{0.0};
    for (const auto& c : contacts) breaks.push_back(c.at);
    breaks.push_back(1.0);
    std::vector<double> lines{0.0};
    for (size_t k = 0; k + 1 < breaks.size(); ++k) {
        int n = cellsFor((breaks[k + 1] - breaks[k]) * length, cell);
        for (int i = 1; i <= n; ++i) lines.push_back(breaks[k] + (breaks[k + 1] - breaks[k]) * i / n);
    }
    return lines;
}

/// Bilinear grid over a (possibly slightly non-planar) convex quad v0 v1 v2 v3. Contact
/// lines (other surfaces standing on the quad) are grid lines, and vertices on the
/// touching part of a contact line are made once for each side: a patch never reaches
/// under a wall, and vertex values never average the two sides of it.
void meshQuad(PatchMesh& mesh, const std::vector<Vec3>& q, int material, int group,
              const scene::MeshingOptions& options, double edge, const QuadContacts& contacts, double tolerance,
              bool withUv, const std::vector<glm::dvec2>& quadUv) {
    const auto [lu, lv] = quadSides(q);
    const auto [cu, cv] = quadCells(q, options, edge);
    int nu = static_cast<int>(cu), nv = static_cast<int>(cv);  // the app's checkPatchCount() keeps these small
    const std::vector<double> S = gridLines(lu, lu / nu * (1 + 1e-9), contacts.constS);
    const std::vector<double> T = gridLines(lv, lv / nv * (1 + 1e-9), contacts.constT);
    nu = static_cast<int>(S.size()) - 1;
    nv = static_cast<int>(T.size()) - 1;

    // The contact line a grid line lies on, if any.
    auto contactAt = [](const std::vector<ContactLine>& lines, double x) -> const ContactLine* {
        for (const auto& l : lines)
            if (std::abs(l.at - x) < 1e-12) return &l;
        return nullptr;
    };
    std::vector<const ContactLine*> onS(S.size()), onT(T.size());
    for (size_t i = 0; i < S.size(); ++i) onS[i] = contactAt(contacts.constS, S[i]);
    for (size_t j = 0; j < T.size(); ++j) onT[j] = contactAt(contacts.constT, T[j]);
    const double su = tolerance / lu, sv = tolerance / lv;
    // Vertex (i, j) as seen from the cell on side (si, sj) of its grid lines (1: the cell
    // lies at higher parameters); one vertex unless a contact line touches there.
    std::map<std::array<int, 4>, uint32_t> ids;
    std::map<uint32_t, glm::dvec2> st;  // each vertex's (s, t) on the quad
    auto at = [&](int i, int j, int si, int sj) {
        if (!onS[i] || !onS[i]->covers(T[j], sv)) si = 0;
        if (!onT[j] || !onT[j]->covers(S[i], su)) sj = 0;
        auto [it, added] = ids.emplace(std::array<int, 4>{i, j, si, sj}, static_cast<uint32_t>(mesh.vertices.size()));
        if (added) {
            double s = S[i], t = T[j];
            mesh.vertices.push_back((1 - s) * (1 - t) * q[0] + s * (1 - t) * q[1] + s * t * q[2] + (1 - s) * t * q[3]);
            st.emplace(it->second, glm::dvec2(s, t));
        }
        return it->second;
    };
    // Texture coordinates: bilinear in (s, t) between the quad's corner coordinates.
    auto patch = [&](uint32_t a, uint32_t b, uint32_t c) {
        if (!withUv) return addPatch(mesh, a, b, c, material, group);
        Uv3 uv{};
        if (quadUv.size() == 4) {
            const uint32_t v[3] = {a, b, c};
            for (int k = 0; k < 3; ++k) {
                const double s = st.at(v[k]).x, t = st.at(v[k]).y;
                uv[k] = (1 - s) * (1 - t) * quadUv[0] + s * (1 - t) * quadUv[1] + s * t * quadUv[2] +
                        (1 - s) * t * quadUv[3];
            }
        }
        addPatch(mesh, a, b, c, material, group, &uv);
    };
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
            uint32_t a = at(i, j, 1, 1), b = at(i + 1, j, 0, 1), c = at(i + 1, j + 1, 0, 0), d = at(i, j + 1, 1, 0);
            if (((i + j) & 1) == 0) {
                patch(a, b, c);
                patch(a, c, d);
            } else {
                patch(a, b, d);
                patch(b, c, d);
            }
        }
}

/// Every triangle into k² lattice triangles; points on an input edge are made once per
/// edge (keyed by its sorted end points), so adjacent triangles share them. New points
/// are appended to `positions`.
std::vector<std::array<uint32_t, 3>> latticeTriangles(std::vector<Vec3>& positions,
                                                      const std::vector<std::array<uint32_t, 3>>& tris, int k) {
    std::map<std::tuple<uint32_t, uint32_t, int>, uint32_t> edgeIds;
    auto add = [&](const Vec3& p) {
        positions.push_back(p);
        return static_cast<uint32_t>(positions.size() - 1);
    };
    auto onEdge = [&](uint32_t a, uint32_t b, int i) {  // point i/k of the way from a to b
        if (i == 0) return a;
        if (i == k) return b;
        if (a > b) std::swap(a, b), i = k - i;
        auto key = std::make_tuple(a, b, i);
        auto it = edgeIds.find(key);
        if (it != edgeIds.end()) return it->second;
        uint32_t id = add(positions[a] + (positions[b] - positions[a]) * (double(i) / k));
        edgeIds.emplace(key, id);
        return id;
    };
    std::vector<std::array<uint32_t, 3>> out;
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
            const Vec3 A = positions[t[0]], B = positions[t[1]], C = positions[t[2]];
            uint32_t id = add(A + (B - A) * (double(i) / k) + (C - A) * (double(j) / k));
            local.emplace(key, id);
            return id;
        };
        for (int j = 0; j < k; ++j)
            for (int i = 0; i + j < k; ++i) {
                out.push_back({P(i, j), P(i + 1, j), P(i, j + 1)});
                if (i + j + 1 < k) out.push_back({P(i + 1, j), P(i + 1, j + 1), P(i, j + 1)});
            }
    }
    return out;
}

/// Premeshing of a triangle group: each triangle by its own size (longest-edge
/// bisection to `edge` metres, conforming where triangles share vertex indices), or,
/// with `triangles_per_surface`, every triangle into the same k² lattice triangles.
/// Corners are shared as the input indexes them, except across creases sharper than
/// crease_angle_deg (splitAtCreases), so vertex values never average across a crease.
void meshTriangles(PatchMesh& mesh, const SurfaceGroup& g, std::vector<std::array<uint32_t, 3>> tris, int group,
                   const scene::MeshingOptions& options, double edge, bool withUv = false,
                   const std::vector<Uv3>& trisUv = {}) {
    std::vector<Vec3> positions = g.positions;
    splitAtCreases(positions, tris, options.creaseAngleDeg);
    const int k = options.trianglesPerSurface > 0 ? latticeFactor(options, tris.size()) : 0;
    std::vector<uint32_t> parents;  // the input triangle each output triangle lies in
    const auto triangles = k > 0 ? latticeTriangles(positions, tris, k) : bisectToSize(positions, tris, edge, &parents);
    if (k > 0)
        for (size_t t = 0; t < triangles.size(); ++t) parents.push_back(static_cast<uint32_t>(t / (size_t(k) * k)));
    std::vector<uint32_t> id(positions.size(), UINT32_MAX);  // local → mesh vertex, made when used
    auto meshVertex = [&](uint32_t v) {
        if (id[v] == UINT32_MAX)
            id[v] = static_cast<uint32_t>(mesh.vertices.size()), mesh.vertices.push_back(positions[v]);
        return id[v];
    };
    for (size_t n = 0; n < triangles.size(); ++n) {
        const auto& t = triangles[n];
        if (!withUv) {
            addPatch(mesh, meshVertex(t[0]), meshVertex(t[1]), meshVertex(t[2]), g.material, group);
            continue;
        }
        Uv3 uv{};
        if (!trisUv.empty()) {  // each corner located in the input triangle it came from
            const auto& parent = tris[parents[n]];
            const std::array<Vec3, 3> corners = {positions[parent[0]], positions[parent[1]], positions[parent[2]]};
            for (int c = 0; c < 3; ++c) uv[c] = uvAt(corners, trisUv[parents[n]], positions[t[c]]);
        }
        addPatch(mesh, meshVertex(t[0]), meshVertex(t[1]), meshVertex(t[2]), g.material, group, &uv);
    }
}

/// A group's polygons as triangles (polygons of more than three corners triangulated);
/// `uvs`, if given, receives each triangle's corner texture coordinates (when the group has them).
std::vector<std::array<uint32_t, 3>> groupTriangles(const SurfaceGroup& g, std::vector<Uv3>* uvs = nullptr) {
    std::vector<std::array<uint32_t, 3>> tris;
    const bool withUv = uvs && g.polygonUvs.size() == g.polygons.size();
    for (size_t n = 0; n < g.polygons.size(); ++n) {
        const auto& poly = g.polygons[n];
        std::vector<std::array<int, 3>> corners = {{0, 1, 2}};
        if (poly.size() != 3) {
            std::vector<Vec3> v;
            for (uint32_t i : poly) v.push_back(g.positions[i]);
            corners.clear();
            for (const auto& t : scene::triangulate(v))
                corners.push_back({static_cast<int>(t[0]), static_cast<int>(t[1]), static_cast<int>(t[2])});
        }
        for (const auto& c : corners) {
            tris.push_back({poly[c[0]], poly[c[1]], poly[c[2]]});
            if (withUv) uvs->push_back({g.polygonUvs[n][c[0]], g.polygonUvs[n][c[1]], g.polygonUvs[n][c[2]]});
        }
    }
    return tris;
}

}  // namespace

double estimatePatchCount(const scene::Scene& scene, const scene::MeshingOptions& options) {
    const double edge = targetEdge(scene, options);
    double count = 0;
    for (const SurfaceGroup& g : scene.groups) {
        if (!scene.isPatchSurface(g)) continue;
        if (g.polygons.size() == 1 && g.polygons[0].size() == 4 && options.premesh) {
            std::vector<Vec3> q;
            for (uint32_t i : g.polygons[0]) q.push_back(g.positions[i]);
            const auto [nu, nv] = quadCells(q, options, edge);
            count += 2 * nu * nv;
            continue;
        }
        const auto tris = groupTriangles(g);
        if (!options.premesh) {
            count += static_cast<double>(tris.size());
        } else if (options.trianglesPerSurface > 0) {
            const double k = latticeFactor(options, tris.size());
            count += k * k * static_cast<double>(tris.size());
        } else {
            for (const auto& t : tris)
                count += bisectedCount(g.positions[t[0]], g.positions[t[1]], g.positions[t[2]], edge);
        }
    }
    return count;
}

PatchMesh premesh(const scene::Scene& scene, const scene::MeshingOptions& options,
                  const std::function<void(double)>& onProgress) {
    PatchMesh mesh;
    const double edge = targetEdge(scene, options);
    CHECK(edge > 0);
    mesh.edgeLength = edge;
    // Room for the estimated count up front: grown by doubling, the arrays would hold up
    // to twice what they need, and three times while they move.
    const double estimate = estimatePatchCount(scene, options);
    mesh.patches.reserve(static_cast<size_t>(1.01 * estimate) + 16);
    mesh.vertices.reserve(static_cast<size_t>(0.6 * estimate) + 16);
    const auto bounds = groupBounds(scene);
    const double tolerance = kContactTolerance * scene.diagonal();
    const bool withUv = !scene.textures.empty();  // then every patch has corner coordinates (0 where untextured)
    for (size_t gi = 0; gi < scene.groups.size(); ++gi) {
        if (onProgress) onProgress(static_cast<double>(gi) / scene.groups.size());
        const SurfaceGroup& g = scene.groups[gi];
        int group = static_cast<int>(gi);
        if (!scene.isPatchSurface(g)) continue;  // mirrors and glass: no radiosity patches
        if (g.polygons.size() == 1 && g.polygons[0].size() == 4 && options.premesh) {
            std::vector<Vec3> q;
            for (uint32_t i : g.polygons[0]) q.push_back(g.positions[i]);
            meshQuad(mesh, q, g.material, group, options, edge, findContacts(scene, gi, q, bounds, tolerance),
                     tolerance, withUv, g.polygonUvs.empty() ? std::vector<glm::dvec2>{} : g.polygonUvs[0]);
            continue;
        }
        std::vector<Uv3> trisUv;
        auto tris = groupTriangles(g, withUv ? &trisUv : nullptr);
        if (options.premesh) {
            meshTriangles(mesh, g, std::move(tris), group, options, edge, withUv, trisUv);
            continue;
        }
        // Premeshing off: the input triangles are the patches, shape as given.
        std::vector<Vec3> positions = g.positions;
        splitAtCreases(positions, tris, options.creaseAngleDeg);
        std::map<uint32_t, uint32_t> ids;
        auto id = [&](uint32_t a) {
            auto [it, added] = ids.emplace(a, static_cast<uint32_t>(mesh.vertices.size()));
            if (added) mesh.vertices.push_back(positions[a]);
            return it->second;
        };
        for (size_t n = 0; n < tris.size(); ++n) {
            const auto& t = tris[n];
            const Uv3 uv = trisUv.empty() ? Uv3{} : trisUv[n];
            addPatch(mesh, id(t[0]), id(t[1]), id(t[2]), g.material, group, withUv ? &uv : nullptr);
        }
    }
    return mesh;
}

PatchMesh meshMirrorBacks(const scene::Scene& scene, const scene::MeshingOptions& options) {
    PatchMesh mesh;
    const double edge = targetEdge(scene, options);
    for (size_t gi = 0; gi < scene.groups.size(); ++gi) {
        const SurfaceGroup& g = scene.groups[gi];
        if (scene.materials[g.material].kind != scene::SurfaceKind::Mirror) continue;
        auto tris = groupTriangles(g);
        for (auto& t : tris) std::swap(t[1], t[2]);  // wound the other way: the normal points out of the back
        meshTriangles(mesh, g, tris, static_cast<int>(gi), options, edge);
    }
    return mesh;
}

}  // namespace rayrad::radiosity
