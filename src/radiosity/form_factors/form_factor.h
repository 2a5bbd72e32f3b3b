// Point-to-polygon form factors: Lambert's analytic formula near, the point approximation far.
#pragma once

#include <core/math.h>

#include <glm/mat3x3.hpp>

#include <array>
#include <vector>

namespace rayrad::radiosity {

/// The angle (radians) between two unit vectors whose cross product has length s ≥ 0 and
/// dot product c: atan2(s, c) in [0, π], by a table of 17 points and a short series
/// (within 2 ulp of the library's atan2 at a fraction of its cost; Lambert's formula
/// takes one per edge).
double edgeAngle(double s, double c);

/// Form factor F(dA_x → polygon), unoccluded, from a differential area at x with unit
/// normal n to a planar polygon with front normal `polyNormal` (Lambert's formula):
///   F = 1/(2π) Σ_i γ_i n·(R_i × R_{i+1}) / |R_i × R_{i+1}|,  R_i = v_i − x.
/// The polygon is clipped to the half space in front of x first; 0 when x is behind the
/// polygon's front face. The illuminance from a uniform polygon of luminance L is π L F.
double formFactorToPolygon(const Vec3& x, const Vec3& n, const Vec3* vertices, int count, const Vec3& polyNormal);

/// Sutherland–Hodgman: the part of the polygon with (p − x)·n ≥ 0, written to `out`
/// (room for 2·count vertices); returns its vertex count.
int clipToFront(const Vec3& x, const Vec3& n, const Vec3* in, int count, Vec3* out);

/// A polygon's vertex v as a receiving point x sees it: d = v − x, r = |d|, dir = d / r
/// (what Lambert's formula starts from; a subdivision shares its vertices' views).
struct VertexView {
    Vec3 d{0.0};
    double r = 0;
    Vec3 dir{0.0};
};
VertexView viewFrom(const Vec3& x, const Vec3& v);

/// formFactorToPolygon for a triangle whose vertices' views from x are known: the same
/// value to the bit.
double formFactorToTriangle(const Vec3& x, const Vec3& n, const Vec3 vertices[3], const VertexView view[3],
                            const Vec3& polyNormal);

/// Point approximation of the same quantity for a small source of area A at `center`:
///   F ≈ A cosθ_x cosθ_s / (π r²), valid when r ≫ the source size.
double formFactorPointApprox(const Vec3& x, const Vec3& n, const Vec3& center, const Vec3& sourceNormal, double area);

/// tr(H M) for the point kernel g(u) = (n·u)(−m·u) / |u|⁴ = cosθ_x cosθ_y / r², u from the
/// receiver x (unit normal n) to a source point (unit normal m): H is g's Hessian in u,
/// M = ∫ (y − c)(y − c)ᵀ dA a source's second moment about the point c = x + u. Then
/// ∫ g dA ≈ A g(u) + ½ tr(H M), the first-order term vanishing about the centroid.
///   H = −(n mᵀ + m nᵀ)/s² − 4 (v uᵀ + u vᵀ)/s³ + 24 a b u uᵀ/s⁴ − 4 a b I/s³,
///   s = |u|², a = n·u, b = −m·u, v = b n − a m.
double pointKernelHessianTrace(const Vec3& u, const Vec3& n, const Vec3& m, const glm::dmat3& M);

/// A triangle's second moment about a point c per unit area, ∫_T (y − c)(y − c)ᵀ dA / A_T
/// = (c_t − c)(c_t − c)ᵀ + Σ_k (v_k − c_t)(v_k − c_t)ᵀ / 12, c_t its centroid (m²).
glm::dmat3 triangleSecondMoment(const Vec3& v0, const Vec3& v1, const Vec3& v2, const Vec3& c);

/// A planar polygon's area centroid and second moment about it, M = ∫ (y − c)(y − c)ᵀ dA
/// (m⁴), from its triangles: per triangle A [(c_t − c)(c_t − c)ᵀ + Σ_k (v_k − c_t)(v_k − c_t)ᵀ / 12].
struct PolygonMoments {
    Vec3 centroid{0.0};
    glm::dmat3 moment{0.0};
};
PolygonMoments polygonMoments(const std::vector<std::array<Vec3, 3>>& triangles);

/// F(dA_x → polygon) far from it, to second order: [A g(u) + ½ tr(H M)] / π about the
/// area centroid (u = centroid − x). Its error falls as (size / distance)⁴: against
/// Lambert's formula at 5 diameters at most 8·10⁻⁴ of F, at grazing angles, and 10⁻⁴ of
/// A / (π r²) (test `second-order polygon form factor`). Valid only with the whole
/// polygon in front of x's plane (the caller checks); 0 when x is behind the polygon.
double formFactorSecondOrder(const Vec3& x, const Vec3& n, const PolygonMoments& polygon, const Vec3& polyNormal,
                             double area);

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
