// The sky's luminance distribution: the CIE standard general skies and the traditional
// CIE overcast sky, relative to the zenith.
#pragma once

#include <core/math.h>

namespace rayrad::scene {

/// Which sky: a uniform sky (L the same everywhere), the traditional CIE overcast sky
/// (Moon & Spencer 1942, CIE 1955), one of the 15 CIE standard general skies
/// (ISO 15469:2004 / CIE S 011/E:2003), or the Perez all-weather sky (Perez, Seals &
/// Michalsky 1993) of one hour's direct and diffuse light (perez.h).
enum class SkyKind { Uniform, CieOvercast, CieStandard, Perez };

/// The five parameters of a CIE standard general sky: gradation a, b and indicatrix c, d, e.
struct CieSkyParameters {
    double a, b, c, d, e;
};

/// The parameters of CIE standard general sky `type` (1 … 15), ISO 15469 table 1.
CieSkyParameters cieSkyParameters(int type);

/// A sky's luminance relative to its zenith's, L(Z, χ) / L_z, at a sky element of zenith
/// angle Z whose angular distance from the sun is χ, the sun at zenith angle Zs:
///   uniform:               1
///   traditional overcast:  (1 + 2 cos Z) / 3
///   CIE standard:          f(χ) φ(Z) / (f(Zs) φ(0)),
///     φ(Z) = 1 + a exp(b / cos Z)  (φ(π/2) = 1),
///     f(χ) = 1 + c (exp(d χ) − exp(d π/2)) + e cos² χ;
///   Perez all-weather:     l(Z, χ) / l(0, Zs), l = max(0, φ(Z) (1 + c exp(d χ) + e cos² χ)),
///     with a … e from the hour's sky (perez.h) and cos Z at least 0.01 in φ (the fit's
///     gradation is not meant for the horizon itself).
class SkyDistribution {
  public:
    SkyDistribution() = default;
    SkyDistribution(SkyKind kind, int cieType, double sunZenithRad);
    /// A Perez all-weather sky with coefficients a … e.
    static SkyDistribution perez(const CieSkyParameters& coefficients, double sunZenithRad);

    /// L / L_z toward the unit direction `local` (x east, y north, z up), z ≥ 0;
    /// `sunLocal` the unit direction of the sun in the same frame.
    double relative(const Vec3& local, const Vec3& sunLocal) const;
    /// ∫ (L / L_z) cos Z dω over the sky hemisphere, sr: the horizontal illuminance of the
    /// sky (lx) per cd/m² of zenith luminance. Analytic for the uniform (π) and the
    /// traditional overcast sky (7π / 9); numerical (a fine midpoint rule) otherwise.
    double horizontalFactor(const Vec3& sunLocal) const;
    /// Whether the distribution depends on where the sun is (types with c or e ≠ 0).
    bool needsSun() const {
        return m_kind == SkyKind::Perez || (m_kind == SkyKind::CieStandard && (m_p.c != 0 || m_p.e != 0));
    }

  private:
    double gradation(double cosZ) const;  ///< φ(Z)
    double indicatrix(double chi) const;  ///< f(χ)
    double perezLuminance(double cosZ, double chi) const;  ///< l(Z, χ)

    SkyKind m_kind = SkyKind::Uniform;
    CieSkyParameters m_p{0, -1, 0, -1, 0};
    double m_norm = 1;  ///< f(Zs) φ(0)
};

}  // namespace rayrad::scene
