// Vertices whose reconstruction extrapolated far beyond the patches around them: gathered
// at a point instead (edge_vertices.h).
#pragma once

#include <radiosity/display/gather_point.h>
#include <radiosity/mesh/patch_mesh.h>
#include <radiosity/solution/solution.h>

#include <cstdint>
#include <vector>

namespace rayrad::radiosity {

/// The share of their mean by which the value at a vertex on a surface's rim may leave
/// the range of the values of the patches around it before the vertex is gathered. A
/// plane fitted to a linear field leaves that range at a rim by about a third of a
/// patch's change; a face two patches wide, fitted across its whole width and
/// extrapolated to its corners, by far more (the Cornell box's short block at `max_edge`
/// 0.1: 5.7 lx at a top corner where a gather reads 16). 0.05: in the Cornell box at
/// `max_edge` 0.1 46 vertices, the image against a gather per pixel median 2.8 → 2.3 %,
/// 95th percentile 21 → 17 % (0.1: 27 vertices, 2.4 / 17.3 %; 0.02: 63, 2.3 / 16.4 %);
/// the hall 287 vertices, the living room about 680.
constexpr double kExtrapolationShare = 0.05;

/// The vertices not yet `taken`, on a surface's rim (their patches do not close around
/// them: vertexAngleSums), of a patch at least `minDiameter` m across (the premesher's
/// patches, as for contacts), whose indirect value (solution.vertexIndirect, the
/// reconstruction) lies outside [min, max] of the open patches' values around them
/// (mesh.covered ones count only where all are covered, as in reconstructVertices) by
/// more than kExtrapolationShare of their mean luminance. Each is gathered where it is,
/// nudged `nudge` m into `patchOf[v]` (its brightest patch), with that patch's normal.
std::vector<GatherPoint> extrapolatedVertices(const PatchMesh& mesh, const RadiositySolution& solution,
                                              const std::vector<int64_t>& patchOf, const std::vector<char>& taken,
                                              double minDiameter, double nudge);

}  // namespace rayrad::radiosity
