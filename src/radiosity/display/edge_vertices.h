// Vertex values from a point gather, not extrapolation: along concave edges and corners, and
// beside outlines where another surface stands on a surface off its mesh lines.
#pragma once

#include <core/visibility.h>
#include <radiosity/clusters/clusters.h>
#include <radiosity/mesh/patch_mesh.h>
#include <radiosity/solution/solution.h>
#include <scene/scene.h>

#include <cstdint>
#include <functional>
#include <vector>

namespace rayrad::radiosity {

/// Patches crossed by an outline are gathered around when at least this fraction of the
/// premesher's edge length across: the patches it made. Smaller ones are an input mesh's
/// own detail (a sofa's cushions pressed into its frame), their band narrower than half a
/// patch; in the living room they are two thirds of the crossed patches (7 766 vertices
/// in all, 2 359 with this bound). The rims of covered parts are bounded alike, and so are
/// the edges that carry seam profiles (seam_profiles.h).
constexpr double kContactMinEdges = 0.5;

/// How many vertices gatherEdgeVertices gathered, by kind.
struct GatheredVertices {
    size_t seams = 0;         ///< vertices on concave edges and corners
    size_t contacts = 0;      ///< vertices beside an outline that crosses their patches
    size_t rims = 0;          ///< vertices on the rim of a covered part (covered_patches.h)
    size_t extrapolated = 0;  ///< vertices whose reconstruction left its patches' range (extrapolated_vertices.h)
    std::vector<uint32_t> seamVertices;  ///< the seam vertices themselves, sorted (seam_profiles.h starts from them)
    /// Seam vertices under a cover, gathered beside it (openGatherPoints), sorted: their
    /// band lies under the cover, and no profile grades it.
    std::vector<uint32_t> seamsGatheredAside;
};

/// Vertices on a concave seam: the vertex lies on a patch of another surface that faces
/// it — on its edge (the edges and corners of a room) or, when the vertex's own patch is
/// one the premesher made, inside it (the foot of a box on a floor whose mesh lines run
/// elsewhere). The indirect light falls steeply there, and no reconstruction from centroid
/// values follows it. Their vertex values are replaced by a final gather at the vertex,
/// iterated `levels` rounds (each round uses the previous round's values at the corners of
/// near patches, as the sensor gather's levels do). A vertex that lies on no other surface
/// keeps the reconstruction, even beside something standing on its surface (the floor's
/// vertices around a box) — unless the outline where they touch crosses a patch's interior
/// (a rotated box on a floor): then the vertices around it are gathered too
/// (contact_vertices.h). So are the vertices on the rim of a covered part (a lamp
/// hung just below a ceiling: mesh.covered), whose reconstruction sees one side only, and
/// the vertices whose reconstruction left the range of the patches around them
/// (extrapolated_vertices.h: the corners of a face a few patches wide).
/// `onProgress` (optional, called from worker threads) gets the
/// fraction done.
GatheredVertices gatherEdgeVertices(const scene::Scene& scene, const PatchMesh& mesh, const Clustering& clustering,
                                    RadiositySolution& solution, const Visibility& vis, int levels,
                                    const std::function<void(double)>& onProgress = {});

}  // namespace rayrad::radiosity
