#include <scene/daylight/sky.h>

#include <core/check.h>

#include <cmath>

namespace rayrad::scene {

CieSkyParameters cieSkyParameters(int type) {
    // ISO 15469:2004 table 1: gradation groups I–VI (a, b), indicatrix groups 1–6 (c, d, e).
    static const CieSkyParameters kTypes[15] = {
        {4.0, -0.70, 0, -1.0, 0},       // 1  overcast, steep gradation, azimuthal uniformity
        {4.0, -0.70, 2, -1.5, 0.15},    // 2  overcast, steep gradation, slight brightening toward the sun
        {1.1, -0.8, 0, -1.0, 0},        // 3  overcast, moderate gradation, azimuthal uniformity
        {1.1, -0.8, 2, -1.5, 0.15},     // 4  overcast, moderate gradation, slight brightening toward the sun
        {0, -1.0, 0, -1.0, 0},          // 5  sky of uniform luminance
        {0, -1.0, 2, -1.5, 0.15},       // 6  partly cloudy, no gradation toward the zenith, slight brightening
        {0, -1.0, 5, -2.5, 0.30},       // 7  partly cloudy, no gradation, brighter circumsolar region
        {0, -1.0, 10, -3.0, 0.45},      // 8  partly cloudy, no gradation, distinct solar corona
        {-1.0, -0.55, 2, -1.5, 0.15},   // 9  partly cloudy, the sun obscured
        {-1.0, -0.55, 5, -2.5, 0.30},   // 10 partly cloudy, brighter circumsolar region
        {-1.0, -0.55, 10, -3.0, 0.45},  // 11 white-blue sky with distinct solar corona
        {-1.0, -0.32, 10, -3.0, 0.45},  // 12 CIE standard clear sky, low luminance turbidity
        {-1.0, -0.32, 16, -3.0, 0.30},  // 13 CIE standard clear sky, polluted atmosphere
        {-1.0, -0.15, 16, -3.0, 0.30},  // 14 cloudless turbid sky with broad solar corona
        {-1.0, -0.15, 24, -2.8, 0.15},  // 15 white-blue turbid sky with broad solar corona
    };
    CHECK(type >= 1 && type <= 15);
    return kTypes[type - 1];
}

SkyDistribution::SkyDistribution(SkyKind kind, int cieType, double sunZenithRad) : m_kind(kind) {
    if (kind != SkyKind::CieStandard) return;
    m_p = cieSkyParameters(cieType);
    m_norm = indicatrix(sunZenithRad) * gradation(1.0);
}

SkyDistribution SkyDistribution::perez(const CieSkyParameters& coefficients, double sunZenithRad) {
    SkyDistribution s;
    s.m_kind = SkyKind::Perez;
    s.m_p = coefficients;
    const double zenith = s.perezLuminance(1.0, sunZenithRad);
    s.m_norm = zenith > 0 ? zenith : 1.0;  // a zenith darker than nothing: the scale still comes from E_dh
    return s;
}

double SkyDistribution::perezLuminance(double cosZ, double chi) const {
    const double c = std::cos(chi);
    const double l = (1 + m_p.a * std::exp(m_p.b / std::max(cosZ, 0.01))) *
                     (1 + m_p.c * std::exp(m_p.d * chi) + m_p.e * c * c);
    return std::max(0.0, l);
}

double SkyDistribution::gradation(double cosZ) const {
    if (cosZ <= 0) return 1.0;  // φ(π/2) = 1: the exponential vanishes at the horizon
    return 1 + m_p.a * std::exp(m_p.b / cosZ);
}

double SkyDistribution::indicatrix(double chi) const {
    const double c = std::cos(chi);
    return 1 + m_p.c * (std::exp(m_p.d * chi) - std::exp(m_p.d * kPi / 2)) + m_p.e * c * c;
}

double SkyDistribution::relative(const Vec3& local, const Vec3& sunLocal) const {
    const double cosZ = std::max(0.0, local.z);
    switch (m_kind) {
        case SkyKind::Uniform: return 1.0;
        case SkyKind::CieOvercast: return (1 + 2 * cosZ) / 3;
        case SkyKind::CieStandard: {
            const double chi = std::acos(std::clamp(glm::dot(local, sunLocal), -1.0, 1.0));
            return indicatrix(chi) * gradation(cosZ) / m_norm;
        }
        case SkyKind::Perez: {
            const double chi = std::acos(std::clamp(glm::dot(local, sunLocal), -1.0, 1.0));
            return perezLuminance(cosZ, chi) / m_norm;
        }
    }
    return 1.0;
}

double SkyDistribution::horizontalFactor(const Vec3& sunLocal) const {
    if (m_kind == SkyKind::Uniform) return kPi;
    if (m_kind == SkyKind::CieOvercast) return 7 * kPi / 9;  // ∫ (1 + 2 cos Z)/3 cos Z dω
    // Midpoint rule in (cos Z, azimuth): dω = d(cos Z) dφ, so the cosine weight is the
    // coordinate itself. Fine enough that the sun's corona (exp(d χ), d ≥ −3) is resolved
    // to better than 10⁻⁴.
    constexpr int kRings = 720, kSectors = 1440;
    double sum = 0;
    for (int i = 0; i < kRings; ++i) {
        const double cosZ = (i + 0.5) / kRings, sinZ = std::sqrt(1 - cosZ * cosZ);
        double ring = 0;
        for (int j = 0; j < kSectors; ++j) {
            const double phi = (j + 0.5) * 2 * kPi / kSectors;
            ring += relative({sinZ * std::cos(phi), sinZ * std::sin(phi), cosZ}, sunLocal);
        }
        sum += ring * cosZ;
    }
    return sum * (1.0 / kRings) * (2 * kPi / kSectors);
}

}  // namespace rayrad::scene
