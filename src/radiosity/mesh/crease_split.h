// Creases in a mesh: a vertex shared by triangles that meet at a sharp angle (a box's
// edge in a model whose importer joined identical positions) becomes one vertex per side.
#pragma once

#include <core/math.h>

#include <array>
#include <cstdint>
#include <vector>

namespace rayrad::radiosity {

/// Gives every smooth side of each vertex a vertex of its own. Around each vertex, two
/// triangles that share an edge through it are on one side when their normals meet within
/// `creaseAngleDeg`; each side after the first gets a copy of the vertex, appended to
/// `positions`, and its triangles are re-indexed to it. A mesh's vertex values are
/// interpolated over the triangles around a vertex: without this, the vertices on a box's
/// top edge would average the top face's light with its sides'. 0 splits nothing.
/// Returns the number of vertices added.
size_t splitAtCreases(std::vector<Vec3>& positions, std::vector<std::array<uint32_t, 3>>& triangles,
                      double creaseAngleDeg);

}  // namespace rayrad::radiosity
