// Which mesh vertices are one point for every patch around them: the direct pass
// evaluates the light there once instead of once per patch.
#pragma once

#include <radiosity/mesh/patch_mesh.h>

#include <vector>

namespace rayrad::radiosity {

/// Per vertex: 1 when the patches around it may share one value at the vertex itself —
/// it lies inside a flat part of one surface (its patches fill the full 2π around it, in
/// one plane), no contact outline runs through it and it is not under a solid. Elsewhere
/// (a surface's rim, which may touch a wall; a contact line, whose vertices are made once
/// per side; a crease of a curved mesh) each patch keeps its own corner point, pulled a
/// hair toward its centroid, on its own side of whatever stands there.
std::vector<char> sharedCorners(const PatchMesh& mesh);

}  // namespace rayrad::radiosity
