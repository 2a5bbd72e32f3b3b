// A scene that is one convex enclosure (an empty box of a room, the paper's cube) has no
// shadows: a segment between two points inside it meets no surface.
#pragma once

#include <core/math.h>

#include <array>
#include <vector>

namespace rayrad::raytrace {

/// The planes of a scene whose occluding triangles all lie in a few planes, with every
/// vertex on or in front of each plane. The points on or in front of all the planes form
/// a convex set and every triangle lies on its boundary, so the open segment between two
/// points of the set meets no triangle: its shadow ray need not be traced. Empty (no
/// planes, contains nothing) when the scene is not such an enclosure or has more than
/// kMaxPlanes planes (a tessellated sphere: testing a point would cost more than a ray).
class ConvexEnclosure {
  public:
    static constexpr size_t kMaxPlanes = 64;

    ConvexEnclosure() = default;
    /// `triangles` with their unit front normals; `tolerance` (m): how far off a plane a
    /// vertex may lie and still be on it (double rounding, far below the ray epsilon).
    ConvexEnclosure(const std::vector<std::array<Vec3, 3>>& triangles, const std::vector<Vec3>& normals,
                    double tolerance);

    bool empty() const { return m_planes.empty(); }
    size_t planeCount() const { return m_planes.size(); }
    /// On or in front of every plane (within the tolerance); false when empty.
    bool contains(const Vec3& p) const;

  private:
    struct Plane {
        Vec3 normal;    ///< unit, into the enclosure
        double offset;  ///< normal · x on the plane (m)
    };
    std::vector<Plane> m_planes;
    double m_tolerance = 0;
};

}  // namespace rayrad::raytrace
