// Discomfort glare from sources seen by an eye: Guth's position index, the Unified Glare
// Rating (CIE 117) and the Daylight Glare Probability (Wienold & Christoffersen 2006).
#pragma once

#include <core/math.h>

#include <optional>
#include <string>
#include <vector>

namespace rayrad::app {

/// An eye and where it looks: the view frame has z along the line of sight, y up (the
/// given up made perpendicular to the line of sight) and x to the right.
struct ViewFrame {
    Vec3 forward{0, 0, -1}, up{0, 1, 0}, right{1, 0, 0};
    /// From a viewing direction and an up direction (neither zero, not parallel).
    static ViewFrame from(const Vec3& direction, const Vec3& up);
    /// A world direction in the view frame (x right, y up, z forward).
    Vec3 toView(const Vec3& w) const { return {glm::dot(w, right), glm::dot(w, up), glm::dot(w, forward)}; }
};

/// Guth's position index P of a source in unit direction `d` of the view frame (the
/// IES handbook's fit to Luckiesh and Guth's table, as evalglare evaluates it):
///   ln P = (35.2 − 0.31889 τ − 1.22 e^(−2τ/9)) 10⁻³ σ + (21 + 0.26667 τ − 0.002963 τ²) 10⁻⁵ σ²
/// σ the angle between the line of sight and the source, τ the angle between the vertical
/// plane through the line of sight and the plane through the line of sight and the source
/// (degrees, 0 straight above, 90 level beside). Below the line of sight (Iwata, as
/// evalglare): τ = 90° and σ = atan(√(x² + (1.15 y)²) / z), a source below weighing as one
/// 1.15 times farther off to the side. Infinite behind the eye (z ≤ 0).
double positionIndex(const Vec3& d);

/// CIE 117's table of position indices ends near P = 16: a source beyond it (more than
/// about 60° above the line of sight) is outside UGR's field of view and does not count.
/// DGP holds P to at most 16 instead, as evalglare does.
constexpr double kMaxPositionIndex = 16;

/// A glare source as the formulas see it.
struct GlareSource {
    double luminance = 0;      ///< L, cd/m² (mean over the source)
    double solidAngle = 0;     ///< ω, sr
    double positionIndex = 1;  ///< P
    Vec3 direction{0, 0, 1};   ///< unit, view frame (x right, y up, z forward)
    std::string name;          ///< the luminaire it is, or "" (a region of an image)
    /// Whether a rendering shows it: area lights, the sky and sunlit surfaces are drawn; a
    /// luminaire (a point light with a distribution) is not.
    bool drawn = true;

    /// L² ω / P², the term each source adds under UGR's and DGP's logarithms, cd²/(m⁴ sr).
    double term() const { return luminance * luminance * solidAngle / (positionIndex * positionIndex); }
};

/// UGR = 8 log10(0.25 / L_b · Σ L² ω / P²) (CIE 117-1995), L_b the background luminance in
/// cd/m², over the sources with P ≤ kMaxPositionIndex. Nothing when no source adds anything
/// (UGR is then below any scale) or L_b is 0.
std::optional<double> unifiedGlareRating(double backgroundLuminance, const std::vector<GlareSource>& sources);

/// DGP = 5.87·10⁻⁵ E_v + 9.18·10⁻² log10(1 + Σ L² ω / (E_v^1.87 P²)) + 0.16 (Wienold &
/// Christoffersen 2006), E_v the vertical illuminance at the eye in lx, P held to at most
/// kMaxPositionIndex; below 1 000 lx
/// multiplied by the low-light correction e^(0.024 E_v − 4) / (1 + e^(0.024 E_v − 4))
/// (Wienold 2009), as evalglare does.
double daylightGlareProbability(double verticalIlluminance, const std::vector<GlareSource>& sources);

/// DGP's class (EN 17037): "imperceptible" below 0.35, "perceptible" below 0.40,
/// "disturbing" below 0.45, "intolerable" from 0.45.
std::string dgpClass(double dgp);

}  // namespace rayrad::app
