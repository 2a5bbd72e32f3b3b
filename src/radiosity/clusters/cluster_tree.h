// Cluster tree: the clusters grouped by normal and position into a binary tree, the levels of the
// hierarchy above clusters. Far from a point, a whole group of clusters counts as one
// source in the final gather's re-gathers (gather.h), as a far node of a cluster's member
// tree does below it: a gather then visits O(log clusters) groups for the far part of the
// scene instead of every cluster.
#pragma once

#include <radiosity/clusters/clusters.h>
#include <radiosity/clusters/far_field.h>
#include <radiosity/mesh/patch_mesh.h>

#include <array>
#include <functional>
#include <vector>

namespace rayrad::radiosity {

/// A group of clusters: order[begin, end) of its tree.
struct ClusterGroup {
    uint32_t begin = 0, end = 0;   ///< range in ClusterTree::order
    uint32_t left = 0, right = 0;  ///< child groups; 0 for a leaf, a single cluster (the root is never a child)
    FarSource far;                 ///< the group's light as one source (a leaf: its cluster's root)
    /// Where its visibility samples go: patch indices (far.rayTo[i] is i for a group, a
    /// sample's own index).
    std::array<uint32_t, 4> rayPatch{};
    double weight = 0;  ///< Σ |Y(L_j)| A_j of its patches (cd), the power its samples split
    /// The widest angle (radians) between a member patch's normal and the group's light
    /// direction (far.normal), bounded from its halves': near 0 for a part of one wall,
    /// 90° or more where the group turns a corner. A group of
    /// one direction is one source as well as a cluster is (its members lie within the
    /// clusters' normal tolerance, and the far field's turning term covers that); around
    /// a corner, members that face away from a point still count in its summed flux (2 % of
    /// a group's light at 4 of its reaches, cluster_tree_test).
    double coneAngle = kPi;
    bool leaf() const { return left == 0; }
    uint32_t size() const { return end - begin; }
};

/// Clusters split by normal where their normals spread by more than about 20°, then at the
/// median of their centroids along the longest extent, down to one cluster per leaf. groups[0] is the root; children
/// follow their parent.
struct ClusterTree {
    std::vector<uint32_t> order;     ///< cluster indices, leaf by leaf
    std::vector<uint32_t> position;  ///< per cluster, its place in `order`
    std::vector<ClusterGroup> groups;
};

/// The tree of `clustering`'s clusters. `clusterFar[c]`: cluster c's own far source (its
/// member tree's root, FarRayTargets::PowerSamples); `luminanceOf(patch)`: the patches'
/// luminance (cd/m², RGB) it was built from. Each group's far source is merged from its
/// halves', in O(clusters) time and memory (not a pass over the patches per level).
ClusterTree clusterTree(const PatchMesh& mesh, const Clustering& clustering, const std::vector<FarSource>& clusterFar,
                        const std::function<Rgb(uint32_t patch)>& luminanceOf);

}  // namespace rayrad::radiosity
