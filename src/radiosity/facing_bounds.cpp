#include <radiosity/facing_bounds.h>

#include <algorithm>
#include <cmath>

namespace rayrad::radiosity {

namespace {
/// A bound must be below −kMargin (|x − c| + r) to skip a node: double rounding of the
/// dot and cross products is ~1e-16 of those lengths.
constexpr double kMargin = 1e-9;
}  // namespace

std::vector<NormalCone> normalCones(const PatchMesh& mesh, const Cluster& cluster, const MemberTree& tree) {
    std::vector<NormalCone> cones(tree.nodes.size());
    for (size_t i = 0; i < tree.nodes.size(); ++i) {
        const MemberNode& node = tree.nodes[i];
        Vec3 sum(0.0);
        for (uint32_t k = node.begin; k < node.end; ++k) sum += mesh.patches[cluster.patches[tree.order[k]]].normal;
        const double length = glm::length(sum);
        if (!(length > 0)) continue;  // no cone: never skipped for facing away
        const Vec3 axis = sum / length;
        double cosHalf = 1;
        for (uint32_t k = node.begin; k < node.end; ++k)
            cosHalf = std::min(cosHalf, glm::dot(axis, mesh.patches[cluster.patches[tree.order[k]]].normal));
        // A cone of 90° or more bounds nothing useful (and its sin would need care).
        if (!(cosHalf > 0)) continue;
        // Widened a little so that the cone holds every normal despite rounding.
        cosHalf = std::max(0.0, cosHalf - 1e-12);
        cones[i] = {axis, cosHalf, std::sqrt(std::max(0.0, 1 - cosHalf * cosHalf))};
    }
    return cones;
}

bool bringsNothing(const MemberNode& node, const NormalCone& cone, const Vec3& x, const Vec3& n) {
    const Vec3 u = x - node.centroid;  // m, from the node's centre to x
    const double r = 0.5 * node.diameter;
    const double margin = kMargin * (glm::length(u) + r);
    // Every corner behind x's tangent plane: (y − x)·n ≤ (c − x)·n + r.
    if (-glm::dot(u, n) + r < -margin) return true;
    // x behind every member's plane.
    if (cone.axis == Vec3(0.0)) return false;
    const double facing = glm::dot(u, cone.axis) * cone.cosHalf + glm::length(glm::cross(u, cone.axis)) * cone.sinHalf;
    return facing + r < -margin;
}

}  // namespace rayrad::radiosity
