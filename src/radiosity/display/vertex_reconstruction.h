// Vertex values from the patches' centroid values: what the image interpolates between.
#pragma once

#include <radiosity/mesh/patch_mesh.h>
#include <radiosity/solution/solution.h>

namespace rayrad::radiosity {

/// Vertex values from the centroid values of the triangles around each vertex (within
/// its surface group). `linear` false: the paper's plain average. `linear` true: a
/// least-squares plane E = a + b u + c w (tangent coordinates at the vertex) through the
/// centroid values of the two rings of triangles around the vertex, evaluated at the
/// vertex; falls back to the average where the points do not span a plane. Covered
/// patches (mesh.covered) count only at a vertex with no open patch around it.
void reconstructVertices(const PatchMesh& mesh, RadiositySolution& solution, bool linear = false);

}  // namespace rayrad::radiosity
