#include <radiosity/clusters/member_tree.h>

#include <algorithm>

namespace rayrad::radiosity {

namespace {

/// Appends the node for order[begin, end) and, when it holds more than leafSize members,
/// its two halves; returns its index.
uint32_t build(const PatchMesh& mesh, const Cluster& C, uint32_t begin, uint32_t end, size_t leafSize,
               MemberTree& tree) {
    const auto index = static_cast<uint32_t>(tree.nodes.size());
    tree.nodes.emplace_back();
    const auto first = tree.order.begin() + begin, last = tree.order.begin() + end;
    auto centroidOf = [&](uint32_t k) -> const Vec3& { return mesh.patches[C.patches[k]].centroid; };

    MemberNode node;
    node.begin = begin, node.end = end;
    double area = 0;
    for (auto k = first; k != last; ++k) {
        const Patch& p = mesh.patches[C.patches[*k]];
        node.centroid += p.area * p.centroid;
        area += p.area;
    }
    node.centroid = area > 0 ? node.centroid / area : centroidOf(*first);
    double r = 0;
    for (auto k = first; k != last; ++k)
        for (int corner = 0; corner < 3; ++corner)
            r = std::max(r, glm::length(mesh.corner(mesh.patches[C.patches[*k]], corner) - node.centroid));
    node.diameter = 2 * r;

    if (end - begin > leafSize) {
        Vec3 lo(1e300), hi(-1e300);
        for (auto k = first; k != last; ++k) lo = glm::min(lo, centroidOf(*k)), hi = glm::max(hi, centroidOf(*k));
        const Vec3 extent = hi - lo;
        const int axis = longestAxis(extent);
        const uint32_t middle = begin + (end - begin) / 2;
        std::nth_element(first, tree.order.begin() + middle, last,
                         [&](uint32_t a, uint32_t b) { return centroidOf(a)[axis] < centroidOf(b)[axis]; });
        node.left = build(mesh, C, begin, middle, leafSize, tree);
        node.right = build(mesh, C, middle, end, leafSize, tree);
    }
    tree.nodes[index] = node;
    return index;
}

}  // namespace

MemberTree memberTree(const PatchMesh& mesh, const Cluster& cluster, size_t leafSize) {
    MemberTree tree;
    tree.order.resize(cluster.patches.size());
    for (uint32_t k = 0; k < tree.order.size(); ++k) tree.order[k] = k;
    if (!tree.order.empty())
        build(mesh, cluster, 0, static_cast<uint32_t>(tree.order.size()), std::max<size_t>(1, leafSize), tree);
    tree.nodes.shrink_to_fit();  // grown by appending: up to twice the nodes' memory otherwise
    return tree;
}

}  // namespace rayrad::radiosity
