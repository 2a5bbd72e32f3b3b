// Covered patches: a patch with a surface just in front of it — the ceiling above a lamp
// hung a centimetre below it, the floor under a low shelf. What such a patch receives is
// not the light of the open surface beside it, so neither the clusters (clusters.h) nor
// the vertex values (display/) mix the two.
#pragma once

#include <core/visibility.h>
#include <radiosity/mesh/patch_mesh.h>

#include <vector>

namespace rayrad::radiosity {

/// How far above a patch its cover is looked for from, × the scene's diagonal.
constexpr double kCoverLift = 2e-5;

/// Per patch, 1 when a surface lies in front of its centroid nearer than a quarter of its
/// size: the segment from `lift` m above the centroid to `lift` + diameter / 4 along its
/// normal is blocked.
std::vector<char> coveredPatches(const PatchMesh& mesh, const Visibility& vis, double lift);

/// A patch is covered when a surface lies in front of it nearer than this many diameters.
constexpr double kCoverDiameters = 0.25;

/// True when a surface lies in front of x (normal n) nearer than `reach` m, looking from
/// `lift` m above it.
bool coveredAt(const Visibility& vis, const Vec3& x, const Vec3& n, double reach, double lift);

}  // namespace rayrad::radiosity
