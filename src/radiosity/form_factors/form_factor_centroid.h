// Where a polygon's light comes from, seen from a point: the form factor's centroid.
// With it, a polygon of linearly varying luminance gives its exact illuminance in one step,
//   E = ∫_P L(y) cosθ_x cosθ_y / r² dA = π F L(c_F),
// where a near patch would otherwise be split toward the point and summed piece by piece.
#pragma once

#include <core/math.h>

namespace rayrad::radiosity {

/// F(dA_x → polygon), unoccluded (Lambert's formula, formFactorToPolygon, on the polygon
/// clipped to the half space in front of x), and the kernel-weighted centroid
///   c_F = ∫_P y K(x, y) dA / F,  K = cosθ_x cosθ_y / (π r²),
/// a point of the (clipped) polygon.
/// With the foot f of x on the polygon's plane (height h above it), y = f + u, and
/// ρ = |u|, the first moment about f is
///   V = ∫ u (n·(y − x)) h / |y − x|⁴ dA = h A₂ n∥ − h² n_m A₁,
///   A₁ = ∫ u / (h² + ρ²)² dA,  A₂ = ∫ u uᵀ / (h² + ρ²)² dA   (n∥, n_m: n along and across the plane),
/// both turned into sums over the edges by the divergence theorem in the plane:
///   A₁ = −½ Σ_e ν_e I₀,   A₂ = −½ Σ_e (p ν_e ν_eᵀ I₀ + τ_e ν_eᵀ I₁) + ½ J 𝟙,
/// edge e at signed distance p from f along its outward normal ν_e, direction τ_e, running
/// from t_a to t_b, a² = h² + p²:  I₀ = ∫ dt / (a² + t²) (atan), I₁ = ∫ t dt / (a² + t²)
/// (log), and J = ∫_P dA / (h² + ρ²) = Σ_e p ∫ ln(1 + (p² + t²)/h²) / (2 (p² + t²)) dt,
/// which has no elementary form (a dilogarithm): Gauss–Legendre in φ, t = a tan φ, where
/// the integrand is smooth. Then c_F = f + V / (π F), π F = h n∥·A₁ − h² n_m A₀ with
/// A₀ = Σ_e p I₀ / (2 h²) from the same edges.
struct FormFactorCentroid {
    double F = 0;        ///< Lambert's form factor (0: nothing of the polygon seen)
    Vec3 centroid{0.0};  ///< c_F (meaningful when F > 0)
};
FormFactorCentroid formFactorCentroid(const Vec3& x, const Vec3& n, const Vec3* vertices, int count,
                                      const Vec3& polyNormal);

}  // namespace rayrad::radiosity
