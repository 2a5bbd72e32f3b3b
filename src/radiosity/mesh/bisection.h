// Premeshing of triangle meshes per element: longest-edge bisection (Rivara 1984).
#pragma once

#include <core/math.h>

#include <array>
#include <cstdint>
#include <vector>

namespace rayrad::radiosity {

/// Splits the triangles (indices into `positions`) until no edge is longer than
/// `maxEdge` metres. Each triangle is refined by its own size — small ones stay whole —
/// and the result is conforming (no T-junctions): a triangle is only ever split at the
/// midpoint of its longest edge, and a marked edge is split in both triangles that share
/// it, the neighbour's longest edge first (closure). Midpoints are appended to
/// `positions`. Triangles sharing an edge must share its two vertex indices. `parents`,
/// if given, receives for each returned triangle the index of the input triangle it lies in.
std::vector<std::array<uint32_t, 3>> bisectToSize(std::vector<Vec3>& positions,
                                                  std::vector<std::array<uint32_t, 3>> triangles, double maxEdge,
                                                  std::vector<uint32_t>* parents = nullptr);

}  // namespace rayrad::radiosity
