// Vertices beside a contact outline (contact_outlines.h): the patches it crosses are part
// lit, part covered, and a vertex value averaged or fitted from them is wrong on both
// sides; such vertices are gathered at a point instead (edge_vertices.h), as the seams of a
// room are.
#pragma once

#include <radiosity/display/gather_point.h>
#include <radiosity/mesh/patch_mesh.h>

#include <cstdint>
#include <vector>

namespace rayrad::radiosity {

/// The vertices of the patches at least `minDiameter` m across that a contact outline
/// crosses (mesh.outlines: findContactOutlines first; none when it was not run). A vertex
/// is gathered where it is (nudged into `patchOf[v]`, its brightest patch), unless it is
/// under a solid (mesh.underSolid: under the box): then at the nearest point of the
/// outlines, moved `nudge` m out in front of that surface, so the part of its triangles
/// that is visible ends at the light beside the outline. A vertex an outline runs through
/// is gathered `nudge` m in front of the surfaces through it (its value serves the points
/// in front: sameSideWeights).
std::vector<GatherPoint> contactVertices(const PatchMesh& mesh, const std::vector<int64_t>& patchOf, double minDiameter,
                                         double nudge);

}  // namespace rayrad::radiosity
