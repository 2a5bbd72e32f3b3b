// Where a point lies on the mesh: the patch under a sensor or a vertex, whether it sits
// on the rim of its surface, and the hair's breadth inside its patch a gather starts from.
#pragma once

#include <core/visibility.h>
#include <radiosity/mesh/patch_mesh.h>
#include <scene/scene.h>

#include <optional>

namespace rayrad::radiosity {

/// Where a point lies on the mesh: patch index and barycentrics (1-u-v, u, v).
struct MeshLocation {
    size_t patch = 0;
    double u = 0, v = 0;
};

/// The patch whose triangle contains x (within a small tolerance) and whose normal
/// agrees with n; nullopt when x is not on any surface. `spatial` (or null): a spatial
/// index over the patches (Visibility::patchesNear), so only the patches near x are
/// looked at; without one, every patch is.
std::optional<MeshLocation> locateOnMesh(const PatchMesh& mesh, const Vec3& x, const Vec3& n, double tolerance,
                                         const Visibility* spatial = nullptr);

/// True when the location lies within `tolerance` (m) of an edge where its surface ends:
/// the rim of a quad, a crease, a contact line (not a diagonal inside a flat grid).
bool onSurfaceBoundary(const PatchMesh& mesh, const MeshLocation& at, double tolerance,
                       const Visibility* spatial = nullptr);

/// Moves a surface point a hair (metres) toward the centroid of its patch, so points on
/// an edge or corner take the limit from inside their own wall.
Vec3 nudgeInside(const PatchMesh& mesh, size_t patch, const Vec3& x, double distance);

/// How far a point is nudged into its own patch (nudgeInside), and how close it must lie to
/// the mesh to be on it (locateOnMesh): 10⁻⁶ of the scene's diagonal, m.
inline double pointNudge(const scene::Scene& scene) { return 1e-6 * scene.diagonal(); }

}  // namespace rayrad::radiosity
