// Vertex values from the patches' centroid values: what the image interpolates between.
#pragma once

#include <radiosity/mesh/patch_mesh.h>
#include <radiosity/solution/solution.h>

namespace rayrad::radiosity {

/// Vertex values from the centroid values of the triangles around each vertex (within
/// its surface group). `linear` false: the paper's plain average. `linear` true: a
/// least-squares fit through the centroid values of the two rings of triangles around the
/// vertex (tangent coordinates u, w at the vertex), evaluated at the vertex — inside a
/// surface, where the ring surrounds the vertex, the quadratic a + b u + c w + d u² + e uw
/// + f w² (a plane lies above a convex field: 8–10 % on the Cornell box's short block);
/// on a surface's rim, or with too few points, the plane a + b u + c w (a quadratic would
/// extrapolate); the average where the points do not span a plane. Covered patches
/// (mesh.covered) count only at a vertex with no open patch around it.
void reconstructVertices(const PatchMesh& mesh, RadiositySolution& solution, bool linear = false);

}  // namespace rayrad::radiosity
