#include <radiosity/form_factors/form_factor.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace rayrad::radiosity {

namespace {

/// A point closer to a polygon's plane than this fraction of its distance to the farthest
/// vertex counts as in the plane (double rounding of coordinates is ~1e-16 relative).
constexpr double kCoplanar = 1e-9;

/// Clipped polygons of up to this many vertices stay on the stack.
constexpr int kStackClipped = 32;

}  // namespace

int clipToFront(const Vec3& x, const Vec3& n, const Vec3* in, int count, Vec3* out) {
    int m = 0;
    for (int i = 0; i < count; ++i) {
        const Vec3& a = in[i];
        const Vec3& b = in[(i + 1) % count];
        double da = glm::dot(a - x, n), db = glm::dot(b - x, n);
        if (da >= 0) out[m++] = a;
        if ((da >= 0) != (db >= 0)) out[m++] = a + (b - a) * (da / (da - db));
    }
    return m;
}

namespace {

/// atan(k / 16) for k = 0 … 16: the points the angle is reduced to.
const std::array<double, 17> kAtanTable = [] {
    std::array<double, 17> t{};
    for (int k = 0; k <= 16; ++k) t[k] = std::atan(k / 16.0);
    return t;
}();

}  // namespace

double edgeAngle(double s, double c) {
    // θ = atan2(s, c), s ≥ 0. With a = min(s, |c|), b = max(s, |c|), t = a / b ≤ 1:
    // atan t = atan t₀ + atan v, t₀ = k/16 the nearest table point, v = (t − t₀)/(1 + t t₀),
    // |v| ≤ 1/32, and atan v = v − v³/3 + … to v¹³ (the rest is below 1e-19 of v);
    // then π/2 − θ when s > |c|, π − θ when c < 0.
    const double ac = std::abs(c);
    const bool steep = s > ac;
    const double a = steep ? ac : s, b = steep ? s : ac;
    const double t = a / b;
    if (!(t >= 0 && t <= 1)) return std::atan2(s, c);  // 0/0, NaN, a negative s
    const int k = static_cast<int>(16 * t + 0.5);
    const double t0 = k / 16.0;
    const double v = k == 0 ? t : (t - t0) / (1 + t * t0), v2 = v * v;  // small angles: one division
    const double series = 1 - v2 * (1. / 3 - v2 * (1. / 5 - v2 * (1. / 7 - v2 * (1. / 9 - v2 * (1. / 11 - v2 / 13)))));
    double theta = kAtanTable[k] + v * series;
    if (steep) theta = 0.5 * kPi - theta;
    return c < 0 ? kPi - theta : theta;
}

namespace {

/// Lambert's sum 1/(2π) Σ_i γ_i n·(R_i × R_{i+1}) / |R_i × R_{i+1}| over the unit
/// directions to a polygon's vertices (all in front of x), clamped to [0, 1].
double lambertSum(const Vec3& n, const Vec3* dir, int count) {
    double sum = 0;
    Vec3 ri = dir[0];
    for (int i = 0; i < count; ++i) {
        Vec3 rj = (i + 1 < count) ? dir[i + 1] : dir[0];
        Vec3 c = glm::cross(ri, rj);
        double s = glm::length(c);
        if (s > 1e-15) {
            double gamma = edgeAngle(s, glm::dot(ri, rj));  // accurate for small and near-π angles
            sum += gamma * glm::dot(n, c) / s;
        }
        ri = rj;
    }
    return std::clamp(std::abs(sum) / (2.0 * kPi), 0.0, 1.0);
}

}  // namespace

VertexView viewFrom(const Vec3& x, const Vec3& v) {
    VertexView view;
    view.d = v - x;
    view.r = glm::length(view.d);
    view.dir = view.r > 0 ? view.d / view.r : view.d;
    return view;
}

namespace {

/// Lambert's formula with the vertices' views from x given by viewOf(i) (computed, or
/// known from a subdivision): formFactorToPolygon's exits, clipping and sum.
template <class ViewOf>
double lambertFormFactor(const Vec3& x, const Vec3& n, const Vec3* vertices, int count, const Vec3& polyNormal,
                         ViewOf viewOf) {
    // One-sided source: x must be in front of the polygon's plane by more than rounding.
    // A point in the plane itself (on the source, or on a coplanar neighbour of it) would
    // otherwise see the polygon fill its whole hemisphere (F = 1) whenever rounding puts
    // it a hair in front: a patch lighting itself, a sensor counting its own wall.
    // Cheap exits first: x behind the polygon's plane, or the polygon wholly behind x's.
    const double height = glm::dot(x - vertices[0], polyNormal);  // m, x above the plane
    if (height <= 0) return 0.0;
    bool anyFront = false;
    for (int i = 0; i < count && !anyFront; ++i) anyFront = glm::dot(vertices[i] - x, n) > 0;
    if (!anyFront) return 0.0;
    // Directions from x to the vertices, unit; their distances give the reach.
    Vec3 dirOnStack[kStackClipped];
    std::vector<Vec3> dirOnHeap;  // emitters with many sides (a 24-gon disk)
    Vec3* dir = dirOnStack;
    if (2 * count > kStackClipped) dirOnHeap.resize(2 * count), dir = dirOnHeap.data();
    double reach = 0;
    bool allFront = true;
    for (int i = 0; i < count; ++i) {
        const VertexView view = viewOf(i);
        reach = std::max(reach, view.r);
        allFront &= glm::dot(view.d, n) >= 0;
        dir[i] = view.dir;
    }
    if (height <= kCoplanar * reach) return 0.0;
    if (!allFront) {
        Vec3 clippedOnStack[kStackClipped];
        std::vector<Vec3> clippedOnHeap;
        Vec3* clipped = clippedOnStack;
        if (2 * count > kStackClipped) clippedOnHeap.resize(2 * count), clipped = clippedOnHeap.data();
        count = clipToFront(x, n, vertices, count, clipped);
        if (count < 3) return 0.0;
        for (int i = 0; i < count; ++i) dir[i] = glm::normalize(clipped[i] - x);
    }
    return lambertSum(n, dir, count);
}

}  // namespace

double formFactorToPolygon(const Vec3& x, const Vec3& n, const Vec3* vertices, int count, const Vec3& polyNormal) {
    return lambertFormFactor(x, n, vertices, count, polyNormal, [&](int i) { return viewFrom(x, vertices[i]); });
}

double formFactorToTriangle(const Vec3& x, const Vec3& n, const Vec3 vertices[3], const VertexView view[3],
                            const Vec3& polyNormal) {
    return lambertFormFactor(x, n, vertices, 3, polyNormal, [&](int i) { return view[i]; });
}

double formFactorPointApprox(const Vec3& x, const Vec3& n, const Vec3& center, const Vec3& sourceNormal, double area) {
    Vec3 d = center - x;
    double r2 = glm::dot(d, d);
    if (r2 <= 0) return 0.0;
    double r = std::sqrt(r2);
    double cosX = glm::dot(n, d) / r;
    double cosS = -glm::dot(sourceNormal, d) / r;
    if (cosX <= 0 || cosS <= 0) return 0.0;
    return area * cosX * cosS / (kPi * r2);
}

double pointKernelHessianTrace(const Vec3& u, const Vec3& n, const Vec3& m, const glm::dmat3& M) {
    const double s = glm::dot(u, u), a = glm::dot(n, u), b = -glm::dot(m, u);
    const double s2 = s * s, ab = a * b;
    const double trace = M[0][0] + M[1][1] + M[2][2];
    return -2 * glm::dot(n, M * m) / s2 - 8 * glm::dot(u, M * (b * n - a * m)) / (s2 * s) +
           24 * ab * glm::dot(u, M * u) / (s2 * s2) - 4 * ab * trace / (s2 * s);
}

glm::dmat3 triangleSecondMoment(const Vec3& v0, const Vec3& v1, const Vec3& v2, const Vec3& c) {
    const Vec3 ct = (v0 + v1 + v2) / 3.0;
    glm::dmat3 second = glm::outerProduct(ct - c, ct - c);
    for (const Vec3& v : {v0, v1, v2}) second += glm::outerProduct(v - ct, v - ct) / 12.0;
    return second;
}

PolygonMoments polygonMoments(const std::vector<std::array<Vec3, 3>>& triangles) {
    PolygonMoments p;
    std::vector<double> areas;
    double area = 0;
    for (const auto& t : triangles) {
        areas.push_back(0.5 * glm::length(glm::cross(t[1] - t[0], t[2] - t[0])));
        p.centroid += areas.back() * (t[0] + t[1] + t[2]) / 3.0;
        area += areas.back();
    }
    if (area <= 0) return p;
    p.centroid /= area;
    for (size_t k = 0; k < triangles.size(); ++k)
        p.moment += areas[k] * triangleSecondMoment(triangles[k][0], triangles[k][1], triangles[k][2], p.centroid);
    return p;
}

double formFactorSecondOrder(const Vec3& x, const Vec3& n, const PolygonMoments& polygon, const Vec3& polyNormal,
                             double area) {
    const Vec3 u = polygon.centroid - x;
    const double s = glm::dot(u, u);
    const double a = glm::dot(n, u), b = -glm::dot(polyNormal, u);
    // b ≤ 0: x is behind the polygon's plane and sees none of it. a ≤ 0 cannot happen with
    // the whole polygon above x's horizon, as the caller ensures, but for rounding.
    if (a <= 0 || b <= 0) return 0.0;
    const double f = area * a * b / (s * s) + 0.5 * pointKernelHessianTrace(u, n, polyNormal, polygon.moment);
    return std::max(0.0, f) / kPi;
}

double triangleSolidAngle(const Vec3& p, const Vec3& v0, const Vec3& v1, const Vec3& v2) {
    Vec3 a = v0 - p, b = v1 - p, c = v2 - p;
    double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
    double numerator = std::abs(glm::dot(a, glm::cross(b, c)));
    double denominator = la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la;
    return 2 * std::atan2(numerator, denominator);  // atan2 keeps Ω > π when the denominator is negative
}

double polygonEtendue(const std::vector<Vec3>& from, const Vec3& facing, const std::vector<Vec3>& to,
                      const Vec3& toFront) {
    // Midpoint rule: each fan triangle of `from` split into k² similar triangles (k(k+1)/2
    // upright, k(k−1)/2 inverted), π F at each one's centroid.
    constexpr int k = 12;
    double sum = 0;
    for (size_t t = 1; t + 1 < from.size(); ++t) {
        const Vec3 a = from[0], u = (from[t] - a) / double(k), v = (from[t + 1] - a) / double(k);
        const double area = 0.5 * glm::length(glm::cross(u, v));  // one small triangle, m²
        for (int i = 0; i < k; ++i)
            for (int j = 0; i + j < k; ++j) {
                const Vec3 corner = a + double(i) * u + double(j) * v;
                sum += area * formFactorToPolygon(corner + (u + v) / 3.0, facing, to.data(), int(to.size()), toFront);
                if (i + j + 1 < k)
                    sum += area * formFactorToPolygon(corner + 2.0 * (u + v) / 3.0, facing, to.data(), int(to.size()),
                                                      toFront);
            }
    }
    return kPi * sum;
}

}  // namespace rayrad::radiosity
