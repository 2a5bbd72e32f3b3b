// Is the scene closed? Light that leaves a surface must land on another one.
#pragma once

#include <core/visibility.h>
#include <radiosity/mesh/patch_mesh.h>

namespace rayrad::radiosity {

/// The fraction of `rays` cosine-distributed rays that reach `farAway` metres without
/// hitting anything, leaving from points spread over the patches in proportion to
/// `weight` (one per patch, e.g. the first reflected flux ρ_i E_i A_i, so surfaces that
/// never see light, like the underside of a box on the floor, do not count);
/// deterministic. 0 for a closed room or sphere. Glass is not seen by visibility rays,
/// so a window counts as an opening.
double escapeFraction(const PatchMesh& mesh, const Visibility& vis, double farAway, const std::vector<double>& weight,
                      int rays = 4096);

/// A scene counts as closed (per-shot conservation applies) when less than this fraction
/// escapes: the closed mirror room lets 1 ray in 4 096 through a crack where two quads
/// meet in single precision. What conservation then puts back is below 0.1 %.
constexpr double kClosedEscapeFraction = 1e-3;

}  // namespace rayrad::radiosity
