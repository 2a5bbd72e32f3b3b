// Vector and colour types shared by every stage (double precision; Embree gets floats).
#pragma once

#include <algorithm>
#include <optional>

#include <glm/glm.hpp>

#include <cmath>
#include <string>
#include <utility>

namespace rayrad {

using Vec3 = glm::dvec3;
using Vec2 = glm::dvec2;

/// Linear Rec.709 RGB triple. Photometric meaning depends on use: illuminance in lx,
/// luminance in cd/m², or a dimensionless reflectance.
using Rgb = glm::dvec3;
/// The same in single precision, for values stored per patch corner where memory
/// counts more than the eighth significant digit.
using RgbF = glm::vec3;

constexpr double kPi = 3.14159265358979323846;

/// Rec.709 luminance weights: Y of a linear Rec.709 triple (lx for illuminance RGB,
/// cd/m² for luminance RGB). A grey triple's Y is its value, exactly (the weighted sum
/// can be an ulp off): a grey scene solved in three channels then makes the same
/// choices, tie for tie, as in one.
inline double luminance(const Rgb& c) {
    if (c.r == c.g && c.g == c.b) return c.g;
    return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}

/// The axis (0, 1, 2) of a box's longest side, `extent` its sides (ties: the lower axis).
inline int longestAxis(const Vec3& extent) {
    return extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
}

inline bool isFinite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// The point of the segment ab nearest to x.
/// The largest magnitude of v's components (the max norm).
inline double maxAbs(const Vec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

/// v scaled to unit length, or nothing when it is zero. Divided by its largest component
/// first, so neither a denormal (1e-320) nor a huge vector over- or underflows on the way.
inline std::optional<Vec3> unitDirection(const Vec3& v) {
    const double largest = maxAbs(v);
    if (!(largest > 0) || !std::isfinite(largest)) return std::nullopt;
    return glm::normalize(v / largest);
}

inline Vec3 closestOnSegment(const Vec3& x, const Vec3& a, const Vec3& b) {
    const Vec3 ab = b - a;
    const double t = glm::clamp(glm::dot(x - a, ab) / glm::max(glm::dot(ab, ab), 1e-300), 0.0, 1.0);
    return a + t * ab;
}

/// Barycentric coordinates (of a, b, c) of x, taken in the triangle's plane; x inside the
/// triangle when none is negative. The triangle must not be degenerate.
inline Vec3 barycentric(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& x) {
    const Vec3 e1 = b - a, e2 = c - a, d = x - a;
    const double p = glm::dot(e1, e1), q = glm::dot(e1, e2), r = glm::dot(e2, e2);
    const double d1 = glm::dot(d, e1), d2 = glm::dot(d, e2);
    const double den = p * r - q * q;
    const double u = (r * d1 - q * d2) / den, v = (p * d2 - q * d1) / den;
    return {1 - u - v, u, v};
}

/// Two unit vectors t1, t2 with (t1, t2, n) a right-handed orthonormal frame, for a unit n.
inline std::pair<Vec3, Vec3> tangentFrame(const Vec3& n) {
    const Vec3 t1 = glm::normalize(glm::cross(n, std::abs(n.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0)));
    return {t1, glm::cross(n, t1)};
}

std::string toString(const Vec3& v);

}  // namespace rayrad
