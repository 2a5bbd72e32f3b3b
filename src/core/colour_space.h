// Linear Rec.709 RGB (sRGB primaries, D65 white; rayrad's working space) and CIE XYZ
// (IEC 61966-2-1 matrices), for white balance, gamut mapping and colour differences.
#pragma once

#include <core/math.h>

#include <cmath>

namespace rayrad {

/// Linear Rec.709 → XYZ, row-major.
constexpr double kRec709ToXyz[3][3] = {{0.4124564, 0.3575761, 0.1804375},
                                       {0.2126729, 0.7151522, 0.0721750},
                                       {0.0193339, 0.1191920, 0.9503041}};
/// XYZ → linear Rec.709, row-major.
constexpr double kXyzToRec709[3][3] = {{3.2404542, -1.5371385, -0.4985314},
                                       {-0.9692660, 1.8760108, 0.0415560},
                                       {0.0556434, -0.2040259, 1.0572252}};
/// The D65 white's X and Z for Y = 1.
constexpr double kD65WhiteX = 0.95047, kD65WhiteZ = 1.08883;

/// The sRGB decoding (IEC 61966-2-1) of one encoded channel value in [0, 1] to linear.
inline double srgbDecode(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }

inline Vec3 rec709ToXyz(const Rgb& c) {
    const auto& m = kRec709ToXyz;
    return Vec3(m[0][0] * c.r + m[0][1] * c.g + m[0][2] * c.b, m[1][0] * c.r + m[1][1] * c.g + m[1][2] * c.b,
                m[2][0] * c.r + m[2][1] * c.g + m[2][2] * c.b);
}

inline Rgb xyzToRec709(const Vec3& xyz) {
    const auto& m = kXyzToRec709;
    return Rgb(m[0][0] * xyz.x + m[0][1] * xyz.y + m[0][2] * xyz.z, m[1][0] * xyz.x + m[1][1] * xyz.y + m[1][2] * xyz.z,
               m[2][0] * xyz.x + m[2][1] * xyz.y + m[2][2] * xyz.z);
}

}  // namespace rayrad
