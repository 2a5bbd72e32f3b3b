// Clusters as mirror images show them: a cluster's members mirrored for a shot through a
// chain of mirrors, and which clusters face a mirror at all.
#pragma once

#include <radiosity/clusters/clusters.h>
#include <radiosity/mesh/patch_mesh.h>
#include <radiosity/mirrors/mirror_images.h>
#include <scene/scene.h>

#include <vector>

namespace rayrad::radiosity {

/// One cluster as an image shows it, with its own copy of its members: `mesh` holds
/// them alone, member k as patch k, so `cluster.patches` is 0 … m−1 (the real cluster's
/// order). Centroid and normal mirrored, the voxel recomputed on the real grid (it may
/// lie outside it). What a shot from an image works with: O(members), built per shot.
struct ImageCluster {
    PatchMesh mesh;
    Cluster cluster;
    /// The real cluster's patch indices (e.g. from powerSamples) as positions in `mesh`.
    ClusterSamples local(const Cluster& real, const ClusterSamples& samples) const;
};
ImageCluster imageCluster(const PatchMesh& mesh, const Clustering& clustering, size_t c, const MirrorImage& image);

/// Per cluster, whether some member faces `mirror` (its centroid in front of the mirror's
/// plane, its front turned toward the polygon: scene::Mirror::facedBy). A cluster none of
/// whose members face a chain's first mirror sends no light into that image; one none of
/// whose members face its last mirror receives none from it.
std::vector<char> clustersFacing(const scene::Mirror& mirror, const PatchMesh& mesh, const Clustering& clustering);

}  // namespace rayrad::radiosity
