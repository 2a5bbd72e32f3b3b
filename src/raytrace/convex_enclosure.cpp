#include <raytrace/convex_enclosure.h>

namespace rayrad::raytrace {

namespace {
/// Two unit normals this close (1 − cos θ, θ ≈ 0.003°) are one plane's.
constexpr double kSameNormal = 1e-9;
}  // namespace

ConvexEnclosure::ConvexEnclosure(const std::vector<std::array<Vec3, 3>>& triangles, const std::vector<Vec3>& normals,
                                 double tolerance)
    : m_tolerance(tolerance) {
    // The distinct planes n·x = d of the triangles, at most kMaxPlanes of them.
    std::vector<Plane> planes;
    for (size_t t = 0; t < triangles.size(); ++t) {
        const Vec3& n = normals[t];
        const double d = glm::dot(n, triangles[t][0]);
        bool known = false;
        for (const Plane& p : planes)
            if (glm::dot(p.normal, n) > 1 - kSameNormal && std::abs(p.offset - d) <= tolerance) known = true;
        if (known) continue;
        if (planes.size() == kMaxPlanes) return;
        planes.push_back({n, d});
    }
    // Every vertex on or in front of every plane: the triangles bound one convex set,
    // their fronts facing into it.
    for (const auto& tri : triangles)
        for (const Vec3& v : tri)
            for (const Plane& p : planes)
                if (glm::dot(p.normal, v) - p.offset < -tolerance) return;
    m_planes = std::move(planes);
}

bool ConvexEnclosure::contains(const Vec3& x) const {
    if (m_planes.empty()) return false;
    for (const Plane& p : m_planes)
        if (glm::dot(p.normal, x) - p.offset < -m_tolerance) return false;
    return true;
}

}  // namespace rayrad::raytrace
