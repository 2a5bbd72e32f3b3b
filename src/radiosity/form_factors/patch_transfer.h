// The patch→patch light transfer used by shooting and by the sensor gather.
#pragma once

#include <radiosity/mesh/patch_mesh.h>

#include <array>

namespace rayrad::radiosity {

/// Unoccluded form factor F(dA_x → patch s) for a receiver point x with normal n:
/// the analytic polygon formula when x is within `analyticDistance` source diameters
/// of the source centroid (where the point approximation would be poor: shared edges,
/// corners), the point approximation beyond. 0 when either side faces away.
double patchFormFactor(const PatchMesh& mesh, const Patch& source, const Vec3& x, const Vec3& n,
                       double analyticDistance);
/// The same for a source given by its corners (a patch as a mirror image shows it).
double patchFormFactor(const std::array<Vec3, 3>& corners, const Patch& source, const Vec3& x, const Vec3& n,
                       double analyticDistance);

}  // namespace rayrad::radiosity
