// Point-to-polygon form factors: Lambert's analytic formula near, the point approximation far.
#pragma once

#include <core/math.h>

#include <vector>

namespace rayrad::radiosity {

/// Form factor F(dA_x → polygon), unoccluded, from a differential area at x with unit
/// normal n to a planar polygon with front normal `polyNormal` (Lambert's formula):
///   F = 1/(2π) Σ_i γ_i n·(R_i × R_{i+1}) / |R_i × R_{i+1}|,  R_i = v_i − x.
/// The polygon is clipped to the half space in front of x first; 0 when x is behind the
/// polygon's front face. The illuminance from a uniform polygon of luminance L is π L F.
double formFactorToPolygon(const Vec3& x, const Vec3& n, const Vec3* vertices, int count, const Vec3& polyNormal);

/// Point approximation of the same quantity for a small source of area A at `center`:
///   F ≈ A cosθ_x cosθ_s / (π r²), valid when r ≫ the source size.
double formFactorPointApprox(const Vec3& x, const Vec3& n, const Vec3& center, const Vec3& sourceNormal, double area);

/// Solid angle (sr) a triangle subtends at p (Van Oosterom & Strackee 1983): with
/// a, b, c the vectors from p to the corners,
///   tan(Ω/2) = |a·(b×c)| / (|a||b||c| + (a·b)|c| + (a·c)|b| + (b·c)|a|).
/// An isotropic point source of intensity I sends I Ω lumens onto the triangle.
double triangleSolidAngle(const Vec3& p, const Vec3& v0, const Vec3& v1, const Vec3& v2);

/// ∫_from π F(dA → to) dA in m² sr: the étendue between two convex polygons, `to`
/// seen from `from`'s side `facing` and lit on its front `toFront`; the inner integral
/// analytic, the outer a midpoint rule on `from` (a few hundred points).
double polygonEtendue(const std::vector<Vec3>& from, const Vec3& facing, const std::vector<Vec3>& to,
                      const Vec3& toFront);

}  // namespace rayrad::radiosity
