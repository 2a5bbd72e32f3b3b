#include <radiosity/mesh/mesh_location.h>

#include <algorithm>
#include <cmath>

namespace rayrad::radiosity {

std::optional<MeshLocation> locateOnMesh(const PatchMesh& mesh, const Vec3& x, const Vec3& n, double tolerance,
                                         const Visibility* spatial) {
    std::optional<MeshLocation> best;
    double bestOutside = tolerance;
    // A patch that qualifies lies within √5 tolerances of x: `outside` ≤ tolerance bounds
    // each barycentric overshoot, so the projection is within 2 tolerances of the triangle
    // (|u e1 + v e2| ≤ (|u| + |v|) · diameter near a corner), and x within one of its plane.
    // Of equally good patches the one of highest index wins, whatever order they are met in.
    forPatchesNear(mesh, spatial, x, 3 * tolerance, [&](uint32_t i) {
        const Patch& p = mesh.patches[i];
        if (glm::dot(p.normal, n) < 0.9) return;
        if (std::abs(glm::dot(x - p.centroid, p.normal)) > tolerance) return;
        // Barycentrics of the projection of x on the triangle.
        const Vec3 &a = mesh.corner(p, 0), &b = mesh.corner(p, 1), &c = mesh.corner(p, 2);
        Vec3 e1 = b - a, e2 = c - a, w = x - a;
        double d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
        double w1 = glm::dot(w, e1), w2 = glm::dot(w, e2);
        double det = d11 * d22 - d12 * d12;
        if (det <= 0) return;
        double u = (d22 * w1 - d12 * w2) / det, v = (d11 * w2 - d12 * w1) / det;
        double outside = std::max({0.0, -u, -v, u + v - 1}) * p.diameter;  // metres outside (0 inside)
        if (outside < bestOutside || (outside == bestOutside && (!best || i > best->patch))) {
            bestOutside = outside;
            u = std::clamp(u, 0.0, 1.0);
            v = std::clamp(v, 0.0, 1.0);
            if (u + v > 1) {
                double s = u + v;
                u /= s, v /= s;
            }
            best = MeshLocation{i, u, v};
        }
    });
    return best;
}

bool onSurfaceBoundary(const PatchMesh& mesh, const MeshLocation& at, double tolerance, const Visibility* spatial) {
    const Patch& p = mesh.patches[at.patch];
    const double w[3] = {1 - at.u - at.v, at.u, at.v};  // weight of corner k
    for (int k = 0; k < 3; ++k) {
        if (w[k] * p.diameter >= tolerance) continue;  // not near the edge opposite corner k
        const uint32_t a = p.v[(k + 1) % 3], b = p.v[(k + 2) % 3];
        // A patch sharing the edge ab has both its ends inside its bounds.
        const Vec3 middle = 0.5 * (mesh.vertices[a] + mesh.vertices[b]);
        bool shared = false;
        forPatchesNear(mesh, spatial, middle, 0.5 * glm::length(mesh.vertices[a] - mesh.vertices[b]), [&](uint32_t i) {
            if (shared || i == at.patch || mesh.patches[i].group != p.group) return;
            const auto& v = mesh.patches[i].v;
            bool hasA = v[0] == a || v[1] == a || v[2] == a, hasB = v[0] == b || v[1] == b || v[2] == b;
            shared = hasA && hasB;
        });
        if (!shared) return true;
    }
    return false;
}

Vec3 nudgeInside(const PatchMesh& mesh, size_t patch, const Vec3& x, double distance) {
    Vec3 toward = mesh.patches[patch].centroid - x;
    double len = glm::length(toward);
    return len > distance ? x + toward * (distance / len) : x;
}

}  // namespace rayrad::radiosity
