// The seam profiles' producer: each edge from a concave seam into its surface gathered at
// 1/2, 1/4 … of its length (solution/seam_profiles.h holds and reads the result).
#pragma once

#include <core/visibility.h>
#include <radiosity/clusters/clusters.h>
#include <radiosity/mesh/patch_mesh.h>
#include <radiosity/solution/seam_profiles.h>
#include <radiosity/solution/solution.h>
#include <scene/scene.h>

#include <cstdint>
#include <functional>
#include <vector>

namespace rayrad::radiosity {

/// Gathers the profiles of every edge at least `minEdge` m long that leaves one of
/// `seamVertices` (sorted) for a vertex that is not one, but for those leaving one of
/// `unprofiled` (sorted: seam vertices whose band a cover hides). A node's δ comes from near-field
/// gathers alone (the patches near the edge, linear from the solution's vertex values):
/// δ(x) = near(x) − ((1 − τ) near(s) + τ near(t)); the light from farther is linear along
/// the edge to second order. Two rounds, the second with the first round's display values
/// refining the near patches (the other wall's band). A profile stops early where the
/// correction at a node is below kSeamProfileTolerance of the light there (the nodes below
/// it then interpolate to 0 at the seam), and one whose first node is below four times
/// it takes no second round. `levels` nodes at most (≤ kNodes). Parallel over edges;
/// each gather serial, so the result does not depend on the thread count. `gathers`
/// (optional) counts the near-field gathers taken.
SeamProfiles gatherSeamProfiles(const scene::Scene& scene, const PatchMesh& mesh, const Clustering& clustering,
                                const RadiositySolution& solution, const Visibility& vis,
                                const std::vector<uint32_t>& seamVertices, const std::vector<uint32_t>& unprofiled,
                                double minEdge, int levels, size_t* gathers = nullptr,
                                const std::function<void(double)>& onProgress = {});

/// A profile's nodes stop where |δ| falls below this fraction of the gathered light (the
/// luminance of each): below it the band is not worth a gather (0.5 %).
constexpr double kSeamProfileTolerance = 0.005;

}  // namespace rayrad::radiosity
