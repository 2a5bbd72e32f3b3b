// The vertices on the rim of a covered part (mesh/covered_patches.h: a lamp hung just below
// a ceiling), and gathered vertices of open patches under a cover: their value is gathered
// in the open beside the cover, not averaged across it.
#pragma once

#include <core/visibility.h>
#include <radiosity/display/gather_point.h>
#include <radiosity/mesh/patch_mesh.h>

#include <cstdint>
#include <vector>

namespace rayrad::radiosity {

/// The vertices on the rim of a covered part (mesh.covered: the corners of covered patches
/// at least `minDiameter` m across that share a corner with an open patch; smaller ones
/// are an imported mesh's own detail, a cushion pressed on a sofa) that `taken` does not
/// hold yet, with where to gather their value: at the
/// vertex (nudged `nudge` m into patchOf[v], its brightest patch) when the vertex itself
/// is open, else at the nearest open point of its patches (looked for on rings of an
/// eighth of its patch's diameter, up to one diameter out), since the part of its
/// triangles one sees lies beside the cover, in the open. `lift`: as for coveredPatches.
std::vector<GatherPoint> rimVertices(const PatchMesh& mesh, const Visibility& vis, const std::vector<int64_t>& patchOf,
                                     const std::vector<char>& taken, double minDiameter, double nudge, double lift);

/// Gather points of open patches (patchOf[vertex] not covered) that lie under a cover
/// themselves — a window's pane fanned out from a vertex under the lip of its frame or its
/// mullion — moved to the nearest open point of the vertex's patches, looked for as for a
/// rim: the value a vertex of an open patch carries is the light where the patch is seen.
/// Returns, per point, whether it was moved.
std::vector<char> openGatherPoints(const PatchMesh& mesh, const Visibility& vis, const std::vector<int64_t>& patchOf,
                                   std::vector<GatherPoint>& points, double lift);

}  // namespace rayrad::radiosity
