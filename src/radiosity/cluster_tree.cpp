#include <radiosity/cluster_tree.h>

#include <tbb/parallel_for.h>

#include <algorithm>

namespace rayrad::radiosity {

namespace {

/// Clusters whose normals differ by more than this in a component (about 20°) are split
/// by normal before position.
constexpr double kNormalSpread = 0.35;

/// Appends the group for order[begin, end) and, when it holds more than one cluster, its
/// two halves; returns its index.
uint32_t build(const Clustering& clustering, uint32_t begin, uint32_t end, ClusterTree& tree) {
    const auto index = static_cast<uint32_t>(tree.groups.size());
    tree.groups.emplace_back();
    ClusterGroup group;
    group.begin = begin, group.end = end;
    if (end - begin > 1) {
        const auto first = tree.order.begin() + begin, last = tree.order.begin() + end;
        const auto middle = [&]() -> uint32_t {
            // Clusters facing different ways are parted first, at the middle of the widest
            // spread of a normal component: a group facing one way can be one source.
            Vec3 lo(1e300), hi(-1e300);
            for (auto c = first; c != last; ++c)
                lo = glm::min(lo, clustering.clusters[*c].normal), hi = glm::max(hi, clustering.clusters[*c].normal);
            Vec3 extent = hi - lo;
            int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
            if (extent[axis] > kNormalSpread) {
                const double cut = 0.5 * (lo[axis] + hi[axis]);
                const auto split = std::partition(first, last, [&](uint32_t c) { return clustering.clusters[c].normal[axis] < cut; });
                return static_cast<uint32_t>(split - tree.order.begin());
            }
            // Then by position: at the median along the centroids' longest extent.
            lo = Vec3(1e300), hi = Vec3(-1e300);
            for (auto c = first; c != last; ++c)
                lo = glm::min(lo, clustering.clusters[*c].centroid), hi = glm::max(hi, clustering.clusters[*c].centroid);
            extent = hi - lo;
            axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
            const uint32_t median = begin + (end - begin) / 2;
            std::nth_element(first, tree.order.begin() + median, last, [&](uint32_t a, uint32_t b) {
                return clustering.clusters[a].centroid[axis] < clustering.clusters[b].centroid[axis];
            });
            return median;
        }();
        group.left = build(clustering, begin, middle, tree);
        group.right = build(clustering, middle, end, tree);
    }
    tree.groups[index] = group;
    return index;
}

}  // namespace

ClusterTree clusterTree(const PatchMesh& mesh, const Clustering& clustering,
                        const std::function<Rgb(uint32_t patch)>& luminanceOf) {
    ClusterTree tree;
    const auto count = static_cast<uint32_t>(clustering.clusters.size());
    tree.order.resize(count);
    for (uint32_t c = 0; c < count; ++c) tree.order[c] = c;
    if (count == 0) return tree;
    build(clustering, 0, count, tree);
    tree.position.resize(count);
    for (uint32_t k = 0; k < count; ++k) tree.position[tree.order[k]] = k;
    // Each group's far source from all its patches (a patch is in one group per level).
    tbb::parallel_for(size_t(0), tree.groups.size(), [&](size_t g) {
        ClusterGroup& group = tree.groups[g];
        if (group.leaf()) return;
        std::vector<uint32_t> members;
        std::vector<Rgb> luminance;
        for (uint32_t k = group.begin; k < group.end; ++k)
            for (uint32_t j : clustering.clusters[tree.order[k]].patches) members.push_back(j), luminance.push_back(luminanceOf(j));
        const Vec3 centre = clustering.clusters[tree.order[group.begin]].centroid;
        group.far = farSource(mesh, members, luminance, centre, FarRayTargets::PowerSamples);
        // Sample i goes to rayPatch[i]: far.rayTo names the samples themselves.
        for (uint32_t i = 0; i < 4; ++i) group.rayPatch[i] = members[group.far.rayTo[i]], group.far.rayTo[i] = i;
        const Vec3 direction(group.far.normal);
        double cone = 1;
        for (uint32_t j : members) cone = std::min(cone, glm::dot(mesh.patches[j].normal, direction));
        group.normalCone = cone;
    });
    return tree;
}

}  // namespace rayrad::radiosity
