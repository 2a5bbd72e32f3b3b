#include <radiosity/contact_vertices.h>

#include <radiosity/gather.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

namespace rayrad::radiosity {

namespace {
/// An outline running closer than this (barycentric) to a patch's edge runs along it.
constexpr double kInteriorMargin = 1e-3;

/// Another surface's triangle whose outline crosses a patch: the outline, a to b (all of
/// it, also beyond the patch), and the triangle's front normal.
struct Crossing {
    Vec3 a{0.0}, b{0.0}, normal{0.0};
};

using Segment = std::pair<Vec3, Vec3>;

/// Barycentric coordinates of x (in the triangle's plane) on the triangle p.
Vec3 barycentric(const std::array<Vec3, 3>& p, const Vec3& x) {
    const Vec3 e1 = p[1] - p[0], e2 = p[2] - p[0], d = x - p[0];
    const double a = glm::dot(e1, e1), b = glm::dot(e1, e2), c = glm::dot(e2, e2);
    const double d1 = glm::dot(d, e1), d2 = glm::dot(d, e2);
    const double den = a * c - b * b;
    const double u = (c * d1 - b * d2) / den, v = (a * d2 - b * d1) / den;
    return {1 - u - v, u, v};
}

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
    const Vec3 la = barycentric(p, ab.first), lb = barycentric(p, ab.second);
    double t0 = 0, t1 = 1;  // the part of a + t (b − a) where every coordinate is ≥ 0
    for (int k = 0; k < 3; ++k) {
        const double s = la[k], e = lb[k] - la[k];
        if (std::abs(e) < 1e-15) {
            if (s < 0) return false;
            continue;
        }
        if (e > 0) t0 = std::max(t0, -s / e);
        else t1 = std::min(t1, -s / e);
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
    const Vec3 t1 = glm::normalize(glm::cross(n, std::abs(n.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0)));
    const Vec3 t2 = glm::cross(n, t1);
    const Vec3 from = x + lift * n;
    for (int k = 0; k < 8; ++k) {
        const double phi = kPi / 4 * k, elevation = k % 2 == 0 ? 0.3 : 1.0;  // rad above the surface
        const Vec3 d = std::cos(elevation) * (std::cos(phi) * t1 + std::sin(phi) * t2) + std::sin(elevation) * n;
        if (!vis.hitsBackFace(from, d)) return false;
    }
    return true;
}

Vec3 closestOnSegment(const Vec3& x, const Vec3& a, const Vec3& b) {
    const Vec3 ab = b - a;
    const double t = std::clamp(glm::dot(x - a, ab) / std::max(glm::dot(ab, ab), 1e-300), 0.0, 1.0);
    return a + t * ab;
}
}  // namespace

std::vector<GatherPoint> contactVertices(const PatchMesh& mesh, const Visibility& vis,
                                         const std::vector<int64_t>& patchOf, double minDiameter, double tolerance,
                                         double nudge) {
    // Per patch, where other surfaces cross its interior (parallel over patches).
    std::vector<std::vector<Crossing>> crossings(mesh.patches.size());
    tbb::parallel_for(size_t(0), mesh.patches.size(), [&](size_t i) {
        const Patch& p = mesh.patches[i];
        if (p.diameter < minDiameter || !(p.area > 0)) return;
        const std::array<Vec3, 3> tri{mesh.corner(p, 0), mesh.corner(p, 1), mesh.corner(p, 2)};
        auto visit = [&](uint32_t j) {
            const Patch& q = mesh.patches[j];
            // Parallel surfaces lie on each other or apart: neither stands on the patch.
            if (q.group == p.group || std::abs(glm::dot(q.normal, p.normal)) > 1 - 1e-9) return;
            const std::array<Vec3, 3> other{mesh.corner(q, 0), mesh.corner(q, 1), mesh.corner(q, 2)};
            const std::optional<Segment> outline = meetsPlane(other, tri[0], p.normal, tolerance);
            if (!outline) return;
            if (crossesInterior(tri, *outline)) crossings[i].push_back({outline->first, outline->second, q.normal});
        };
        if (!vis.patchesNear(p.centroid, p.diameter, visit))
            for (size_t j = 0; j < mesh.patches.size(); ++j) visit(static_cast<uint32_t>(j));
    });

    // Per vertex, the crossings of the patches around it.
    std::vector<std::vector<uint32_t>> crossed(mesh.vertices.size());
    for (uint32_t i = 0; i < mesh.patches.size(); ++i)
        if (!crossings[i].empty())
            for (uint32_t v : mesh.patches[i].v) crossed[v].push_back(i);
    std::vector<GatherPoint> points;
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
        if (crossed[v].empty() || patchOf[v] < 0) continue;
        const Vec3& x = mesh.vertices[v];
        const Patch& own = mesh.patches[patchOf[v]];
        bool hidden = true;  // behind every crossing surface: under the box
        const Crossing* nearest = nullptr;
        Vec3 foot = x;  // the nearest point of the outlines
        double best = std::numeric_limits<double>::infinity();
        for (uint32_t i : crossed[v])
            for (const Crossing& c : crossings[i]) {
                const Vec3 y = closestOnSegment(x, c.a, c.b);
                hidden &= glm::dot(c.normal, x - y) < -tolerance;
                if (glm::length(y - x) < best) best = glm::length(y - x), foot = y, nearest = &c;
            }
        hidden = hidden && insideSolid(vis, x, own.normal, nudge);
        if (!hidden) {
            points.push_back({v, nudgeInside(mesh, static_cast<size_t>(patchOf[v]), x, nudge), own.normal});
            continue;
        }
        // Out from under: `nudge` in front of the nearest crossing surface, in the surface's plane.
        Vec3 at = foot + nudge * nearest->normal;
        at -= glm::dot(own.normal, at - x) * own.normal;
        points.push_back({v, at, own.normal});
    }
    return points;
}

}  // namespace rayrad::radiosity
