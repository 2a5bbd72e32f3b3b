// Shading normals for images: a curved mesh's triangles shaded with normals interpolated
// from their corners, so its facets do not show. The radiosity keeps the true normals.
#pragma once

#include <radiosity/mesh/patch_mesh.h>

namespace rayrad::radiosity {

/// Fills mesh.cornerNormal: the normal at corner k of patch i is the area-weighted mean of
/// the normals of the patches around that mesh vertex (vertices are shared only within a
/// surface group) that meet patch i's normal within `smoothingAngleDeg`; a crease sharper
/// than that keeps each side's own normal. Left empty when no corner's normal differs from
/// its patch's (flat surfaces only) or the angle is 0.
void computeShadingNormals(PatchMesh& mesh, double smoothingAngleDeg);

/// The shading normal at barycentric (u, v) of patch i: interpolated from its corners and
/// normalised, or the patch's own normal when there are none (or they degenerate).
Vec3 shadingNormal(const PatchMesh& mesh, size_t i, double u, double v);

/// Where to shade the point at barycentric (u, v) of patch i from: on a smoothed patch, the
/// point lifted toward the smooth surface its corner normals describe (Hanika, "Hacking the
/// shadow terminator", Ray Tracing Gems II, 2021: the point projected onto each corner's
/// tangent plane where it lies below it, the three interpolated), so shadow rays leave from
/// above the neighbouring facets and the terminator shows no facets either; else the point.
Vec3 shadingPoint(const PatchMesh& mesh, size_t i, double u, double v);

}  // namespace rayrad::radiosity
