// Contact outlines: where another surface stands on (or passes through) a patch off the
// patch's mesh lines — a turned box on a floor, an imported sofa on a carpet, a screen
// standing in an office. The premesher's contact lines cut a quad only along its grid;
// these are the outlines it could not follow. The vertex values around them are gathered
// (contact_vertices.h), and the indirect light inside a crossed patch is interpolated
// from the vertices on the hit point's own side of the outline.
#pragma once

#include <core/visibility.h>
#include <radiosity/mesh/contact_lines.h>  // kContactTolerance
#include <radiosity/mesh/patch_mesh.h>

#include <array>
#include <optional>
#include <vector>

namespace rayrad::radiosity {

/// Fills mesh.outlineBegin / mesh.outlines: for each patch, the triangles of other
/// surface groups that meet its plane (within `tolerance` m), rise in front of it, and
/// cross its interior — not only along its edges or through a corner (an outline the mesh
/// was cut along is no crossing). And mesh.throughBegin / throughNormals: the vertices
/// of crossed patches that such an outline runs through (within `tolerance`). Parallel surfaces never cross. And
/// mesh.underSolid: the crossed patches' vertices behind every outline crossing them (by more than `tolerance`) from
/// which rays, leaving `lift` m above the surface in eight directions, meet only back faces (under a box, not behind a
/// lone panel). `vis` should have a spatial index (patchesNear; else every patch pair is examined) and tell back faces
/// (hitsBackFace; else no vertex is under a solid).
void findContactOutlines(PatchMesh& mesh, const Visibility& vis, double tolerance, double lift);

/// Barycentric weights (of corners 0, 1, 2) for the point (1 − u − v, u, v) of patch i,
/// leaving out the corners across an outline crossing the patch (the segment from the
/// point to the corner crosses it) that are not under a solid — their values are the
/// light of the outline's other side; a corner under a solid carries the light at the
/// outline (contact_vertices.h) and stays. A corner an outline runs through carries the
/// light in front of it (contact_vertices.h) and is left out for points behind every
/// outline through it, also in the patches around it that the outline only touches.
/// Renormalised; the plain weights when neither applies, or when no corner would be left.
std::array<double, 3> sameSideWeights(const PatchMesh& mesh, size_t i, double u, double v);

/// Where the light of a vertex x under a solid is taken (mesh.underSolid): the nearest
/// point of the outlines crossing `patches`, `nudge` m in front of the standing surface
/// there, in the plane through x with unit normal n. Nothing when no outline crosses them.
std::optional<Vec3> inFrontOfOutline(const PatchMesh& mesh, const Vec3& x, const Vec3& n,
                                     const std::vector<uint32_t>& patches, double nudge);

}  // namespace rayrad::radiosity
