// Clusters: patches grouped by the voxel holding their centroid and by normal direction.
#pragma once

#include <core/visibility.h>
#include <radiosity/mesh/patch_mesh.h>
#include <scene/scene.h>
#include <scene/settings.h>

#include <array>
#include <string>
#include <vector>

namespace rayrad::radiosity {

/// Four member patches (indices into PatchMesh::patches) whose centroids carry visibility rays.
using ClusterSamples = std::array<uint32_t, 4>;

/// A group of patches that shoots and receives as one far away (the upper of the two
/// hierarchy levels). Geometry only; the solver keeps the light.
struct Cluster {
    std::vector<uint32_t> patches;  ///< indices into PatchMesh::patches
    std::array<int, 3> voxel{};     ///< the voxel holding every member's centroid
    double area = 0;                ///< A_C = Σ A_i, m²
    Vec3 centroid{0.0};             ///< area-weighted
    Vec3 normal{0.0};               ///< area-weighted mean normal, unit
    /// |Σ A_i n_i| in m²: the projected area toward directions all members face
    /// (≤ area; equal for a planar cluster). Used by the point approximation.
    double projectedArea = 0;
    double diameter = 0;       ///< twice the largest centroid-to-vertex distance, m
    Rgb meanReflectance{0.0};  ///< area-weighted ρ
    ClusterSamples samples{};  ///< spread over the members (receiving; see powerSamples)
    bool planar = false;       ///< all members in one plane
};

/// The voxel grid and its clusters. Every patch belongs to exactly one cluster; a
/// cluster of one patch is a "patch in no cluster" in the paper's words.
struct Clustering {
    Vec3 origin{0.0};
    double voxelSize = 0;         ///< m
    double derivedVoxelSize = 0;  ///< m, before the crowding bound shrank it (0: given as voxel_size)
    std::array<int, 3> dims{};
    std::vector<Cluster> clusters;
    std::vector<uint32_t> clusterOf;  ///< patch → cluster
    bool enabled = false;

    /// Chebyshev distance between two clusters' voxels: max(|x−i|, |y−j|, |z−k|).
    int voxelDistance(const Cluster& a, const Cluster& b) const;
    size_t multiPatchClusters() const;
    std::string statistics() const;
};

/// The occupied voxels as balls holding their clusters: a shot or a gather through a
/// mirror tests these first (MirrorImage::mayPass) and skips every cluster of a voxel no
/// light can pass through the chain to or from. A cluster's ball (centroid, half its
/// diameter) lies inside its voxel's, so a voxel that fails the test leaves its clusters
/// nothing to pass (the segments from any point of the ball stay within its radius of
/// the centre's segment).
struct VoxelRegions {
    struct Region {
        Vec3 centre{0.0};   ///< the voxel's centre
        double radius = 0;  ///< m: reaches every member cluster's ball
    };
    std::vector<Region> regions;
    std::vector<uint32_t> regionOf;  ///< per cluster, its voxel's index in `regions`
};
VoxelRegions voxelRegions(const Clustering& clustering);

/// Per cluster, the other clusters it touches, sorted: a corner of one of its patches lies
/// on a patch of the other (within `tolerance`, m) — a concave seam, a contact line, or
/// two neighbours on one curved surface (neighbours in one plane exchange nothing) — or in
/// front of it across a gap narrower than kTouchingGap of the two patches (a block
/// modelled a little above a floor). Their
/// form factor is singular along the line where they meet, which a cluster's few sample
/// points cannot follow, so they exchange patch→patch however weak the shot (shooting_core).
/// `spatial` is a spatial index over the patches (Visibility::patchesNear).
std::vector<std::vector<uint32_t>> touchingClusters(const PatchMesh& mesh, const Clustering& clustering,
                                                    const Visibility& spatial, double tolerance);

/// Visibility samples for a cluster sending light: four members stratified by their
/// share of `power` (one value per member, e.g. the unshot flux ΔL_i A_i), so the rays
/// leave from where the light is. A cluster on a wall partly hidden behind a mirror
/// 1 cm away has its lit members beside the mirror and its dark ones behind it; the
/// fixed samples could all lie behind it and lose the lit members' light. Falls back
/// to `samples` when no member has power.
ClusterSamples powerSamples(const Cluster& c, const std::vector<double>& power);

/// The voxel edge the options ask for (resolves the derived defaults, then shrinks a
/// derived edge while the voxels are crowded: ClusterOptions::maxVoxelCrowding).
double clusterVoxelSize(const scene::Scene& scene, const PatchMesh& mesh, const scene::ClusterOptions& options);
/// The derived edge before the crowding bound: from patchesPerCluster or sizePercent.
double derivedVoxelSize(const scene::Scene& scene, const PatchMesh& mesh, const scene::ClusterOptions& options);
/// Σ_v n_v² / N: the patches a patch shares its voxel with, on average (itself included),
/// on the cluster grid of voxels of `edge` m over the scene's bounds.
double voxelCrowding(const PatchMesh& mesh, const scene::Scene& scene, double edge);

/// Builds the clusters. With options.enabled false every patch is its own cluster.
/// Deterministic: patches are visited in index order and join the first cluster of
/// their voxel whose first member's normal is within the tolerance and, given `vis`,
/// which that member can see: a cluster must never make a patch receive or send light
/// for surfaces it cannot see, so floor patches on the two sides of a thin wall, a
/// poster and the wall behind it, a shelf and the floor below it are never one cluster.
/// (Two members see each other when the segment between their centroids, lifted off
/// their surfaces, is unoccluded; the lift grows with the angle between their normals
/// so a curved surface does not hide its own members.)
Clustering buildClusters(const scene::Scene& scene, const PatchMesh& mesh, const scene::ClusterOptions& options,
                         const Visibility* vis = nullptr);

}  // namespace rayrad::radiosity
