#include <radiosity/mesh/contact_outlines.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

namespace rayrad::radiosity {

namespace {
/// An outline running closer than this (barycentric) to a patch's edge runs along it.
constexpr double kInteriorMargin = 1e-3;
/// How far past its ends (a share of the patch's diameter) an outline piece blocks a corner
/// in sameSideWeights. A contact line comes in pieces that end where the other surface's
/// patches end, not where this patch's edges are, and a piece that crosses only a sliver
/// of the patch is not listed (kInteriorMargin): a gap is left between the listed piece's
/// end and the patch's edge. A corner just beyond the line (a wall's top corner 0.3 mm
/// above the ceiling that meets it) was then seen through the gap from the points beside
/// that edge, and a dark line ran down the wall along the mesh edge.
constexpr double kOutlineOverreach = 0.01;

using Segment = std::pair<Vec3, Vec3>;

/// The segment along which triangle t meets the plane through c with unit normal n, when
/// t also rises in front of the plane (a corner more than `tol` in front): corners within
/// `tol` of the plane and the points where t's edges cross it, projected onto it.
std::optional<Segment> meetsPlane(const std::array<Vec3, 3>& t, const Vec3& c, const Vec3& n, double tol) {
    double d[3];
    bool rises = false;
    for (int k = 0; k < 3; ++k) {
        d[k] = glm::dot(n, t[k] - c);
        rises |= d[k] > tol;
    }
    if (!rises) return std::nullopt;
    std::array<Vec3, 3> on;
    int count = 0;
    for (int k = 0; k < 3; ++k) {
        const int l = (k + 1) % 3;
        if (std::abs(d[k]) <= tol) on[count++] = t[k];
        if ((d[k] < -tol && d[l] > tol) || (d[k] > tol && d[l] < -tol))
            if (count < 3) on[count++] = t[k] + (d[k] / (d[k] - d[l])) * (t[l] - t[k]);
    }
    if (count < 2) return std::nullopt;  // touches at a point, or not at all
    Segment s{on[0], on[1]};
    for (int i = 0; i < count; ++i)  // the two farthest apart
        for (int j = i + 1; j < count; ++j)
            if (glm::length(on[i] - on[j]) > glm::length(s.first - s.second)) s = {on[i], on[j]};
    s.first -= glm::dot(n, s.first - c) * n;
    s.second -= glm::dot(n, s.second - c) * n;
    return s;
}

/// True when the segment ab (in the triangle's plane) runs through triangle p's interior,
/// not only along an edge or through a corner.
bool crossesInterior(const std::array<Vec3, 3>& p, const Segment& ab) {
    const Vec3 la = barycentric(p[0], p[1], p[2], ab.first), lb = barycentric(p[0], p[1], p[2], ab.second);
    double t0 = 0, t1 = 1;  // the part of a + t (b − a) where every coordinate is ≥ 0
    for (int k = 0; k < 3; ++k) {
        const double s = la[k], e = lb[k] - la[k];
        if (std::abs(e) < 1e-15) {
            if (s < 0) return false;
            continue;
        }
        if (e > 0)
            t0 = std::max(t0, -s / e);
        else
            t1 = std::min(t1, -s / e);
    }
    if (!(t1 - t0 > 1e-9)) return false;
    const Vec3 mid = la + 0.5 * (t0 + t1) * (lb - la);
    return std::min({mid[0], mid[1], mid[2]}) > kInteriorMargin;
}

/// True when x, on a surface with unit normal n, is inside a closed solid: rays from just
/// above x in eight directions over its hemisphere all meet a back face first. (Behind a
/// lone panel standing on the floor — a screen, a wall drawn as one quad — the rays that
/// leave away from the panel reach the room.)
bool insideSolid(const Visibility& vis, const Vec3& x, const Vec3& n, double lift) {
    const auto [t1, t2] = tangentFrame(n);
    const Vec3 from = x + lift * n;
    for (int k = 0; k < 8; ++k) {
        const double phi = kPi / 4 * k, elevation = k % 2 == 0 ? 0.3 : 1.0;  // rad above the surface
        const Vec3 d = std::cos(elevation) * (std::cos(phi) * t1 + std::sin(phi) * t2) + std::sin(elevation) * n;
        if (!vis.hitsBackFace(from, d)) return false;
    }
    return true;
}

/// Which side of the line through a and b (in the plane with normal n) p lies on: the
/// sign of n · ((b − a) × (p − a)).
double side(const Vec3& n, const Vec3& a, const Vec3& b, const Vec3& p) {
    return glm::dot(n, glm::cross(b - a, p - a));
}

/// True when the segments pq and ab (in the plane with normal n) cross.
bool segmentsCross(const Vec3& n, const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b) {
    return side(n, a, b, p) * side(n, a, b, q) < 0 && side(n, p, q, a) * side(n, p, q, b) < 0;
}
}  // namespace

void findContactOutlines(PatchMesh& mesh, const Visibility& vis, double tolerance, double lift) {
    // Per patch (in parallel), then packed.
    std::vector<std::vector<ContactOutline>> found(mesh.patches.size());
    tbb::parallel_for(size_t(0), mesh.patches.size(), [&](size_t i) {
        const Patch& p = mesh.patches[i];
        if (!(p.area > 0)) return;
        const std::array<Vec3, 3> tri{mesh.corner(p, 0), mesh.corner(p, 1), mesh.corner(p, 2)};
        auto visit = [&](uint32_t j) {
            const Patch& q = mesh.patches[j];
            // Parallel surfaces lie on each other or apart: neither stands on the patch.
            if (q.group == p.group || std::abs(glm::dot(q.normal, p.normal)) > 1 - 1e-9) return;
            const std::array<Vec3, 3> other{mesh.corner(q, 0), mesh.corner(q, 1), mesh.corner(q, 2)};
            const std::optional<Segment> outline = meetsPlane(other, tri[0], p.normal, tolerance);
            if (outline && crossesInterior(tri, *outline))
                found[i].push_back({outline->first, outline->second, q.normal});
        };
        forPatchesNear(mesh, &vis, p.centroid, p.diameter, visit);
    });
    mesh.outlineBegin.assign(mesh.patches.size() + 1, 0);
    mesh.outlines.clear();
    for (size_t i = 0; i < mesh.patches.size(); ++i) {
        mesh.outlines.insert(mesh.outlines.end(), found[i].begin(), found[i].end());
        mesh.outlineBegin[i + 1] = static_cast<uint32_t>(mesh.outlines.size());
    }

    // The vertices of crossed patches that lie under a solid standing on them: behind
    // every outline crossing their patches, and inside a closed solid.
    mesh.underSolid.assign(mesh.vertices.size(), 0);
    std::vector<char> behind(mesh.vertices.size(), 0);  // 0: no outline, 1: behind all so far, 2: not
    std::vector<Vec3> normalOf(mesh.vertices.size(), Vec3(0.0));
    for (size_t i = 0; i < mesh.patches.size(); ++i)
        for (uint32_t o = mesh.outlineBegin[i]; o < mesh.outlineBegin[i + 1]; ++o)
            for (uint32_t v : mesh.patches[i].v) {
                const ContactOutline& c = mesh.outlines[o];
                const Vec3& x = mesh.vertices[v];
                const bool back = glm::dot(c.normal, x - closestOnSegment(x, c.a, c.b)) < -tolerance;
                if (behind[v] != 2) behind[v] = back ? 1 : 2;
                normalOf[v] = mesh.patches[i].normal;
            }
    tbb::parallel_for(size_t(0), mesh.vertices.size(), [&](size_t v) {
        if (behind[v] == 1 && insideSolid(vis, mesh.vertices[v], normalOf[v], lift)) mesh.underSolid[v] = 1;
    });

    // The vertices an outline runs through (within `tolerance`), with its front normal.
    std::vector<std::vector<Vec3>> through(mesh.vertices.size());
    for (size_t i = 0; i < mesh.patches.size(); ++i)
        for (uint32_t o = mesh.outlineBegin[i]; o < mesh.outlineBegin[i + 1]; ++o)
            for (uint32_t v : mesh.patches[i].v) {
                const ContactOutline& c = mesh.outlines[o];
                const Vec3& x = mesh.vertices[v];
                if (glm::length(x - closestOnSegment(x, c.a, c.b)) > tolerance) continue;
                auto& normals = through[v];
                if (std::none_of(normals.begin(), normals.end(),
                                 [&](const Vec3& m) { return glm::dot(m, c.normal) > 1 - 1e-9; }))
                    normals.push_back(c.normal);
            }
    mesh.throughBegin.assign(mesh.vertices.size() + 1, 0);
    mesh.throughNormals.clear();
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
        mesh.throughNormals.insert(mesh.throughNormals.end(), through[v].begin(), through[v].end());
        mesh.throughBegin[v + 1] = static_cast<uint32_t>(mesh.throughNormals.size());
    }
}

std::array<double, 3> sameSideWeights(const PatchMesh& mesh, size_t i, double u, double v) {
    const std::array<double, 3> plain{1 - u - v, u, v};
    if (mesh.outlineBegin.empty()) return plain;
    const Patch& p = mesh.patches[i];
    auto hasThrough = [&](int k) {
        auto [first, last] = mesh.outlinesThrough(p.v[k]);
        return first != last;
    };
    const bool crossed = mesh.outlineBegin[i] != mesh.outlineBegin[i + 1];
    if (!crossed && !hasThrough(0) && !hasThrough(1) && !hasThrough(2)) return plain;
    const Vec3 x = mesh.pointAt(p, u, v);
    std::array<double, 3> w{std::max(0.0, plain[0]), std::max(0.0, plain[1]), std::max(0.0, plain[2])};
    double sum = 0;
    for (int k = 0; k < 3; ++k) {
        // A corner under a solid keeps its weight: its value is the light at the outline.
        if (!mesh.underSolid[p.v[k]]) {
            const Vec3 corner = mesh.corner(p, k);
            auto [first, last] = mesh.outlinesThrough(p.v[k]);
            if (first != last) {
                // On an outline: its value is the light in front, for points in front of one.
                if (std::none_of(first, last, [&](const Vec3& normal) { return glm::dot(normal, x - corner) >= 0; }))
                    w[k] = 0;
            } else {
                for (uint32_t o = mesh.outlineBegin[i]; o < mesh.outlineBegin[i + 1] && w[k] != 0; ++o) {
                    const ContactOutline& line = mesh.outlines[o];
                    const Vec3 reach = kOutlineOverreach * p.diameter * glm::normalize(line.b - line.a);
                    if (segmentsCross(p.normal, x, corner, line.a - reach, line.b + reach)) w[k] = 0;
                }
            }
        }
        sum += w[k];
    }
    if (!(sum > 1e-9)) return plain;
    for (double& wk : w) wk /= sum;
    return w;
}

std::optional<Vec3> inFrontOfOutline(const PatchMesh& mesh, const Vec3& x, const Vec3& n,
                                     const std::vector<uint32_t>& patches, double nudge) {
    const ContactOutline* nearest = nullptr;
    Vec3 foot = x;
    double best = std::numeric_limits<double>::infinity();
    for (uint32_t i : patches)
        for (uint32_t o = mesh.outlineBegin[i]; o < mesh.outlineBegin[i + 1]; ++o) {
            const Vec3 y = closestOnSegment(x, mesh.outlines[o].a, mesh.outlines[o].b);
            if (glm::length(y - x) < best) best = glm::length(y - x), foot = y, nearest = &mesh.outlines[o];
        }
    if (!nearest) return std::nullopt;
    const Vec3 at = foot + nudge * nearest->normal;
    return at - glm::dot(n, at - x) * n;
}

}  // namespace rayrad::radiosity
