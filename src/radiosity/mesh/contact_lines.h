// Contact lines: where other surfaces stand on, lean against or cut through a quad, so the
// premesher can cut the quad's patches there (no patch reaches under a wall into the
// next room) and keep vertex values on the two sides apart.
#pragma once

#include <core/math.h>
#include <scene/scene.h>

#include <array>
#include <vector>

namespace rayrad::radiosity {

/// Surfaces closer than this (× the scene's diagonal) to a surface's plane touch it: for
/// the premesher's contact lines and for contact outlines alike.
constexpr double kContactTolerance = 1e-6;

/// A gap narrower than this share of the patches on either side of it is a contact at the
/// mesh's resolution: across it the light changes as steeply, at the patches' scale, as
/// where two surfaces meet (a block modelled 2 mm above a floor meshed in 4 cm patches),
/// so the clusters on its two sides exchange light patch→patch (touchingClusters).
constexpr double kTouchingGap = 0.1;

/// A line of constant parameter on a quad q(s, t) = q0 + s (q1 − q0) + t (q3 − q0).
struct ContactLine {
    double at = 0;                               ///< the constant parameter, in (0, 1)
    std::vector<std::array<double, 2>> covered;  ///< ranges of the other parameter where a surface touches
    /// True when the other parameter value x lies on a touching range (within `tol`).
    bool covers(double x, double tol) const;
};

/// Contact lines of one quad: lines s = const (running along t) and t = const.
struct QuadContacts {
    std::vector<ContactLine> constS, constT;  ///< sorted by `at`, merged within the tolerance
};

/// Axis-aligned bounds of each surface group (for a quick rejection), metres.
std::vector<std::array<Vec3, 2>> groupBounds(const scene::Scene& scene);

/// The lines along which other surfaces (not glass: it casts no shadow) touch or cross
/// the quad `q` (group `group`) from its front side. Only for a planar parallelogram —
/// other quads get none — and only lines parallel to one of its edges: the walls,
/// partitions and cabinets that architects draw on a floor's grid. `tolerance` in metres.
QuadContacts findContacts(const scene::Scene& scene, size_t group, const std::vector<Vec3>& q,
                          const std::vector<std::array<Vec3, 2>>& bounds, double tolerance);

}  // namespace rayrad::radiosity
