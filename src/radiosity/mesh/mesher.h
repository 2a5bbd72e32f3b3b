// Premeshing: every input polygon becomes well-shaped triangles (the radiosity patches).
#pragma once

#include <functional>

#include <radiosity/mesh/patch_mesh.h>
#include <scene/scene.h>

namespace rayrad::radiosity {

/// Quads become an n_u × n_v grid of cells, two triangles each (diagonals alternate, so
/// a square wall gives 2n² equal triangles); cells are kept within maxCellAspect, so a
/// sliver becomes many compact triangles. Other polygons are triangulated and each
/// triangle bisected along its longest edge until no edge exceeds the target (its own
/// size decides, conforming where triangles share corners: no T-junctions); with
/// `triangles_per_surface`, every triangle of a group into the same k² lattice triangles.
/// `onProgress` gets the fraction of surface groups done.
PatchMesh premesh(const scene::Scene& scene, const scene::MeshingOptions& options,
                  const std::function<void(double)>& onProgress = {});

/// The backs of the mirrors, as triangles (normals out of the backs) of about the
/// premesher's size. Mirrors take no part in the radiosity, but light that reaches a
/// mirror's back is absorbed there and the direct pass books it.
PatchMesh meshMirrorBacks(const scene::Scene& scene, const scene::MeshingOptions& options);

/// The number of patches premesh() would make, estimated from the input alone (no
/// allocation), so absurd settings are caught before they are tried. Within a factor of
/// about 2 of the real count (contact lines and slivers add some).
double estimatePatchCount(const scene::Scene& scene, const scene::MeshingOptions& options);

/// The edge length the mesher aims for (resolves the automatic default); the mesh it makes
/// carries it (PatchMesh::edgeLength).
double targetEdge(const scene::Scene& scene, const scene::MeshingOptions& options);

}  // namespace rayrad::radiosity
