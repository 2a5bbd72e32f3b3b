// Vertices beside an outline where another surface stands on (or passes through) a
// surface without a mesh line there: a rotated box on a floor, an imported sofa on a
// carpet. The patches the outline crosses are part lit, part covered, and a vertex value
// averaged or fitted from them is wrong on both sides; such vertices are gathered at a
// point instead (edge_vertices.h), as the seams of a room are.
#pragma once

#include <core/visibility.h>
#include <radiosity/patch_mesh.h>

#include <cstdint>
#include <vector>

namespace rayrad::radiosity {

/// A vertex whose indirect value is gathered at `at` (on its surface, normal `normal`).
struct GatherPoint {
    size_t vertex = 0;
    Vec3 at{0.0};
    Vec3 normal{0.0};
};

/// The vertices of patches at least `minDiameter` m across whose interior another
/// surface's outline crosses. The outline
/// is where a triangle of another surface group meets the patch's plane (within
/// `tolerance` m) and rises in front of it; an outline running along the patch's edges (a
/// contact line or a seam the mesh was cut along) does not count. A vertex in front of
/// one of the crossing surfaces is gathered where it is (nudged into `patchOf[v]`, its
/// brightest patch); a vertex behind all of them and inside a closed solid (under the box:
/// rays from it meet only backs) is gathered at the nearest point of the outline, moved
/// `nudge` m out in front of that surface, so the part of its triangles that is visible
/// ends at the light beside the outline. `vis` should have a spatial index (patchesNear;
/// else every patch pair is examined) and tell back faces (hitsBackFace; else no vertex
/// counts as under a solid).
std::vector<GatherPoint> contactVertices(const PatchMesh& mesh, const Visibility& vis,
                                         const std::vector<int64_t>& patchOf, double minDiameter, double tolerance,
                                         double nudge);

}  // namespace rayrad::radiosity
