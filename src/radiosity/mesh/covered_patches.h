// Covered patches: a patch with a surface just in front of it — the ceiling above a lamp
// hung a centimetre below it, the floor under a low shelf. What such a patch receives is
// not the light of the open surface beside it, so neither the clusters (clusters.h) nor
// the vertex values (solution.h, edge_vertices.h) mix the two.
#pragma once

#include <core/visibility.h>
#include <radiosity/display/contact_vertices.h>  // GatherPoint
#include <radiosity/mesh/patch_mesh.h>

#include <vector>

namespace rayrad::radiosity {

/// How far above a patch its cover is looked for from, × the scene's diagonal.
constexpr double kCoverLift = 2e-5;

/// Per patch, 1 when a surface lies in front of its centroid nearer than a quarter of its
/// size: the segment from `lift` m above the centroid to `lift` + diameter / 4 along its
/// normal is blocked.
std::vector<char> coveredPatches(const PatchMesh& mesh, const Visibility& vis, double lift);

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

}  // namespace rayrad::radiosity
