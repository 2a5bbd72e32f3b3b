// Member groups: a cluster's patches split into small compact groups, so that a receiver
// a few group diameters away sees a whole group through one visibility ray. This is the
// patch→patch near field's third level: far enough for a shared ray, too near for the
// cluster→cluster approximation.
#pragma once

#include <radiosity/clusters.h>
#include <radiosity/patch_mesh.h>

#include <vector>

namespace rayrad::radiosity {

struct MemberGroup {
    std::vector<uint32_t> members;  ///< positions k in Cluster::patches
    Vec3 centroid{0.0};             ///< area-weighted, m
    double diameter = 0;            ///< twice the largest centroid-to-corner distance, m
};

/// Per cluster, its members in groups of at most `maxSize`: the members' centroids are
/// split at the median along their longest extent until each part is small enough.
std::vector<std::vector<MemberGroup>> memberGroups(const PatchMesh& mesh, const Clustering& clustering, size_t maxSize);

}  // namespace rayrad::radiosity
