#include <radiosity/form_factors/form_factor_centroid.h>

#include <radiosity/form_factors/form_factor.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace rayrad::radiosity {

namespace {

/// Polygons of up to this many vertices (before clipping) stay on the stack.
constexpr int kStackVertices = 8;

/// The edge sums' π F and Lambert's agree within this share, or the centroid is the
/// clipped polygon's vertex mean.
constexpr double kAgreement = 1e-6;

/// Gauss–Legendre nodes and weights on [−1, 1], 4 points (the test against a fine
/// subdivision finds the centroid within 8e-5 of a 1 m triangle with them, 1e-5 with 8).
constexpr std::array<double, 4> kNodes = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                                          0.8611363115940526};
constexpr std::array<double, 4> kWeights = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                                            0.3478548451374538};

/// p ∫_{ta}^{tb} ln(1 + (p² + t²)/h²) / (2 (p² + t²)) dt, an edge's share of
/// J = ∫_P dA / (h² + ρ²). With t = a tan φ, a² = h² + p², it is
///   (p / 2a) ∫ [ln(1 + p²/h²) − ln cos²φ] / (sin²φ + (p/a)² cos²φ) dφ,
/// smooth in φ (the ratio tends to 1 where numerator and denominator both vanish, p ≪ h,
/// φ → 0), with a logarithmic end only where the edge runs far past a (x close to its line,
/// where the factor p or the caller's h makes the share small).
double edgeShareOfJ(double p, double h, double a, double ta, double tb) {
    const double phiA = std::atan(ta / a), phiB = std::atan(tb / a);
    const double half = 0.5 * (phiB - phiA), mid = 0.5 * (phiA + phiB);
    const double lnA = std::log1p((p / h) * (p / h));
    const double alpha2 = (p / a) * (p / a);
    double sum = 0;
    for (size_t k = 0; k < kNodes.size(); ++k) {
        const double phi = mid + half * kNodes[k];
        const double s = std::sin(phi), s2 = s * s, c2 = 1 - s2;
        sum += kWeights[k] * (lnA - std::log1p(-s2)) / (s2 + alpha2 * c2);
    }
    return p / (2 * a) * half * sum;
}

}  // namespace

FormFactorCentroid formFactorCentroid(const Vec3& x, const Vec3& n, const Vec3* vertices, int count,
                                      const Vec3& polyNormal) {
    FormFactorCentroid out;
    // The part in front of x, clipped once: Lambert's formula and the edge sums both take it.
    bool allFront = true;
    for (int i = 0; i < count; ++i) allFront &= glm::dot(vertices[i] - x, n) >= 0;
    std::array<Vec3, 2 * kStackVertices> onStack;
    std::vector<Vec3> onHeap;
    Vec3* buffer = onStack.data();
    if (count > kStackVertices) onHeap.resize(2 * static_cast<size_t>(count)), buffer = onHeap.data();
    const Vec3* clipped = allFront ? vertices : buffer;
    const int m = allFront ? count : clipToFront(x, n, vertices, count, buffer);
    if (m < 3) return out;
    out.F = formFactorToPolygon(x, n, clipped, m, polyNormal);
    if (!(out.F > 0)) return out;
    Vec3 areaCentroid(0.0);
    for (int i = 0; i < m; ++i) areaCentroid += clipped[i] / double(m);
    out.centroid = areaCentroid;  // in case the sums below fail
    const Vec3& normal = polyNormal;
    const double h = glm::dot(x - clipped[0], normal);  // m, > 0 (F > 0)
    const Vec3 foot = x - h * normal;
    const double nAcross = glm::dot(n, normal);  // n_m
    const Vec3 nAlong = n - nAcross * normal;    // n∥
    // Outward in-plane edge normals: ν = τ × m for a polygon counter-clockwise about m.
    Vec3 twiceArea(0.0);
    for (int i = 0; i < m; ++i) twiceArea += glm::cross(clipped[i] - foot, clipped[(i + 1) % m] - foot);
    const double orientation = glm::dot(twiceArea, normal) >= 0 ? 1.0 : -1.0;
    Vec3 sumNuI0(0.0), sumEdgeA2(0.0);  // Σ ν I₀;  Σ (p ν I₀ + τ I₁)(ν·n∥)
    double sumPI0 = 0, J = 0;           // Σ p I₀;  J
    for (int i = 0; i < m; ++i) {
        const Vec3 from = clipped[i], to = clipped[(i + 1) % m];
        const double length = glm::length(to - from);
        if (!(length > 0)) continue;
        const Vec3 tau = (to - from) / length;
        const Vec3 nu = orientation * glm::cross(tau, normal);
        const Vec3 u = from - foot;
        const double p = glm::dot(u, nu), ta = glm::dot(u, tau), tb = ta + length;
        const double a2 = h * h + p * p, a = std::sqrt(a2);
        const double I0 = (std::atan(tb / a) - std::atan(ta / a)) / a;
        const double I1 = 0.5 * std::log((a2 + tb * tb) / (a2 + ta * ta));
        const double nuN = glm::dot(nu, nAlong);
        sumNuI0 += I0 * nu;
        sumPI0 += p * I0;
        sumEdgeA2 += nuN * (p * I0 * nu + I1 * tau);
        if (p != 0) J += edgeShareOfJ(p, h, a, ta, tb);
    }
    // π F = h n∥·A₁ − h² n_m A₀ and V = h A₂ n∥ − h² n_m A₁ (see the header).
    const Vec3 A1 = -0.5 * sumNuI0;
    const double piF = h * glm::dot(nAlong, A1) - 0.5 * nAcross * sumPI0;
    const Vec3 V = h * (-0.5 * sumEdgeA2 + 0.5 * J * nAlong) - h * h * nAcross * A1;
    // The sums agree with Lambert's formula to rounding; where they do not (a polygon
    // seen edge-on, F ~ 1e-20, the terms cancelling), the centroid is not to be trusted.
    const bool agrees = std::abs(piF - kPi * out.F) <= kAgreement * kPi * out.F;
    if (agrees && std::isfinite(glm::dot(V, V))) out.centroid = foot + V / piF;
    return out;
}

}  // namespace rayrad::radiosity
