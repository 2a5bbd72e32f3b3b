// Member tree: a cluster's patches split recursively into compact halves, the levels of
// the hierarchy below a cluster. Far from a receiver a whole node counts as one source
// (the final gather's far field); its leaves are the member groups that share one
// visibility ray in the shooting's patch→patch near field.
#pragma once

#include <radiosity/clusters/clusters.h>
#include <radiosity/mesh/patch_mesh.h>

#include <vector>

namespace rayrad::radiosity {

/// A node of a member tree: the members order[begin, end) of its tree.
struct MemberNode {
    uint32_t begin = 0, end = 0;   ///< range in MemberTree::order
    uint32_t left = 0, right = 0;  ///< child nodes; 0 for a leaf (the root is never a child)
    Vec3 centroid{0.0};            ///< area-weighted, m
    double diameter = 0;           ///< twice the largest centroid-to-corner distance, m
    bool leaf() const { return left == 0; }
    uint32_t size() const { return end - begin; }
};

/// One cluster's tree: the members' centroids are split at the median along their
/// longest extent until a part has at most the leaf size. nodes[0] is the root (the
/// whole cluster); children follow their parent, left subtree first.
struct MemberTree {
    std::vector<uint32_t> order;  ///< positions k in Cluster::patches, leaf by leaf
    std::vector<MemberNode> nodes;
};

MemberTree memberTree(const PatchMesh& mesh, const Cluster& cluster, size_t leafSize);

/// Depth first through `tree` from its root: `visit(index, node)` returns true to open
/// the node (its children follow, left first) or false when it has dealt with the node
/// itself (a far node as one source, a leaf member by member). Leaves are never opened.
template <class Visit>
void descend(const MemberTree& tree, Visit&& visit) {
    uint32_t stack[128];  // the tree is at most 32 deep (median splits of < 2³² members)
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const uint32_t index = stack[--top];
        const MemberNode& node = tree.nodes[index];
        if (visit(index, node) && !node.leaf()) {
            stack[top++] = node.right;
            stack[top++] = node.left;
        }
    }
}

}  // namespace rayrad::radiosity
