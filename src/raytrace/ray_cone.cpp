#include <raytrace/ray_cone.h>

#include <algorithm>
#include <cmath>

namespace rayrad::raytrace {

std::pair<Vec3, Vec3> surfaceFootprint(double width, const Vec3& d, const Vec3& n) {
    constexpr double kMaxStretch = 32;
    const double cosTheta = std::abs(glm::dot(d, n));
    Vec3 along = d - glm::dot(d, n) * n;  // the ray's direction projected onto the surface
    const double length = glm::length(along);
    if (length > 1e-9) {
        along /= length;
    } else {  // head-on: the footprint is a circle; any direction in the plane will do
        along = glm::normalize(std::abs(n.x) < 0.9 ? glm::cross(n, Vec3(1, 0, 0)) : glm::cross(n, Vec3(0, 1, 0)));
    }
    const Vec3 across = glm::cross(n, along);
    const double stretch = std::min(kMaxStretch, 1 / std::max(cosTheta, 1 / kMaxStretch));
    return {width * stretch * along, width * across};
}

}  // namespace rayrad::raytrace
