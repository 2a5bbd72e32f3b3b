// Point-to-polygon form factors against closed forms from the catalogue.
#include <radiosity/form_factors/form_factor.h>

#include <core/random.h>

#include "test_support.h"

#include <algorithm>
#include <array>

#include <cmath>
#include <vector>

using namespace rayrad;
using namespace rayrad::radiosity;

namespace {

double toPolygon(const Vec3& x, const Vec3& n, const std::vector<Vec3>& poly, const Vec3& polyNormal) {
    return formFactorToPolygon(x, n, poly.data(), static_cast<int>(poly.size()), polyNormal);
}

/// Rectangle [0,a]×[0,b] in the plane z = c, facing down (−z), CCW seen from below.
std::vector<Vec3> ceilingRect(double a, double b, double c) {
    return {{0, 0, c}, {0, b, c}, {a, b, c}, {a, 0, c}};
}

}  // namespace

TEST_CASE("differential area to a coaxial parallel disc: F = R^2 / (R^2 + h^2)", "[form_factor]") {
    for (double h : {0.1, 1.0, 3.0}) {
        const double R = 1.0;
        const int n = 2048;  // a regular 2048-gon; its area is within 1.6e-6 of the disc's
        std::vector<Vec3> poly;
        for (int i = 0; i < n; ++i) {
            double t = -2 * kPi * i / n;  // clockwise seen from above = CCW seen from below
            poly.push_back({R * std::cos(t), R * std::sin(t), h});
        }
        double f = toPolygon({0, 0, 0}, {0, 0, 1}, poly, {0, 0, -1});
        CHECK(f == Approx(R * R / (R * R + h * h)).epsilon(1e-5));
    }
}

TEST_CASE("differential area below the corner of a parallel rectangle (catalogue B-1)", "[form_factor]") {
    // F = 1/(2π) [ A/√(1+A²) atan(B/√(1+A²)) + B/√(1+B²) atan(A/√(1+B²)) ], A = a/c, B = b/c
    for (auto [a, b, c] : {std::tuple{1.0, 1.0, 1.0}, std::tuple{2.0, 0.5, 0.7}, std::tuple{0.1, 5.0, 2.0}}) {
        double A = a / c, B = b / c;
        double expected = (A / std::sqrt(1 + A * A) * std::atan(B / std::sqrt(1 + A * A)) +
                           B / std::sqrt(1 + B * B) * std::atan(A / std::sqrt(1 + B * B))) /
                          (2 * kPi);
        CHECK(toPolygon({0, 0, 0}, {0, 0, 1}, ceilingRect(a, b, c), {0, 0, -1}) == Approx(expected).epsilon(1e-12));
    }
}

TEST_CASE("differential area at the foot of a perpendicular rectangle (catalogue B-3)", "[form_factor]") {
    // Element at the origin, normal +z; rectangle y in [0, b], z in [0, c] in the plane
    // x = a, facing −x (it rises from the element's plane). With X = a/b, Y = c/b:
    // F = 1/(2π) [ atan(1/X) − X/√(X²+Y²) atan(1/√(X²+Y²)) ]
    // (checked against 1500² midpoint quadrature to 1e-7 when this test was written).
    for (auto [a, b, c] : {std::tuple{1.0, 1.0, 1.0}, std::tuple{0.5, 2.0, 1.0}, std::tuple{2.0, 1.0, 3.0}}) {
        std::vector<Vec3> rect = {{a, 0, 0}, {a, 0, c}, {a, b, c}, {a, b, 0}};  // normal −x
        double X = a / b, Y = c / b;
        double expected =
            (std::atan(1 / X) - X / std::sqrt(X * X + Y * Y) * std::atan(1 / std::sqrt(X * X + Y * Y))) / (2 * kPi);
        CHECK(toPolygon({0, 0, 0}, {0, 0, 1}, rect, {-1, 0, 0}) == Approx(expected).epsilon(1e-12));
    }
}

TEST_CASE("a point inside a closed cube sees the five other faces with total form factor 1", "[form_factor]") {
    // Unit cube, the point on the floor; faces CCW seen from inside.
    Vec3 x(0.3, 0.6, 0.0), n(0, 0, 1);
    std::vector<std::pair<std::vector<Vec3>, Vec3>> faces = {
        {{{0, 0, 1}, {0, 1, 1}, {1, 1, 1}, {1, 0, 1}}, {0, 0, -1}},  // ceiling
        {{{0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {1, 0, 0}}, {0, 1, 0}},   // y = 0
        {{{0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}}, {0, -1, 0}},  // y = 1
        {{{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}}, {1, 0, 0}},   // x = 0
        {{{1, 0, 0}, {1, 0, 1}, {1, 1, 1}, {1, 1, 0}}, {-1, 0, 0}},  // x = 1
    };
    double sum = 0;
    for (const auto& [poly, normal] : faces) sum += toPolygon(x, n, poly, normal);
    CHECK(sum == Approx(1.0).epsilon(1e-12));
}

TEST_CASE("one-sided: a polygon seen from behind or behind the receiver gives 0", "[form_factor]") {
    auto rect = ceilingRect(1, 1, 1);
    CHECK(toPolygon({0.5, 0.5, 2}, {0, 0, -1}, rect, {0, 0, -1}) == 0.0);  // above the emitting side's back
    CHECK(toPolygon({0.5, 0.5, 0}, {0, 0, -1}, rect, {0, 0, -1}) == 0.0);  // receiver faces away
}

TEST_CASE("clipping: only the part in front of the receiver counts", "[form_factor]") {
    // A vertical wall x = 0 (normal +x) spanning z in [-1, 1]; a receiver on the floor
    // z = 0 facing +z sees only its upper half.
    std::vector<Vec3> wall = {{0, -1, -1}, {0, 1, -1}, {0, 1, 1}, {0, -1, 1}};
    std::vector<Vec3> upper = {{0, -1, 0}, {0, 1, 0}, {0, 1, 1}, {0, -1, 1}};
    Vec3 x(0.4, 0.1, 0), n(0, 0, 1);
    CHECK(toPolygon(x, n, wall, {1, 0, 0}) == Approx(toPolygon(x, n, upper, {1, 0, 0})).epsilon(1e-12));
}

TEST_CASE("the point approximation converges to the analytic value far away", "[form_factor]") {
    std::vector<Vec3> tri = {{0, 0, 10}, {0, 0.1, 10}, {0.1, 0, 10}};
    Vec3 c = (tri[0] + tri[1] + tri[2]) / 3.0;
    double exact = toPolygon({0, 0, 0}, {0, 0, 1}, tri, {0, 0, -1});
    double approx = formFactorPointApprox({0, 0, 0}, {0, 0, 1}, c, {0, 0, -1}, 0.005);
    CHECK(approx == Approx(exact).epsilon(1e-4));
}

TEST_CASE("second-order polygon form factor against Lambert's formula", "[form_factor]") {
    // A 0.6 m troffer and a 24-gon disk, seen from random points at k of their diameters
    // with random normals that keep the whole polygon above the horizon: the error is
    // relative to A/(π r²) (the scale of the light's contribution), and falls as (d/r)⁴.
    auto triangles = [](const std::vector<Vec3>& poly) {
        std::vector<std::array<Vec3, 3>> t;
        for (size_t i = 1; i + 1 < poly.size(); ++i) t.push_back({poly[0], poly[i], poly[i + 1]});
        return t;
    };
    std::vector<Vec3> disk;
    for (int i = 0; i < 24; ++i) {
        const double t = -2 * kPi * i / 24;
        disk.push_back({0.4 * std::cos(t), 0.4 * std::sin(t), 0});
    }
    const std::vector<std::vector<Vec3>> lights = {{{-0.3, -0.3, 0}, {-0.3, 0.3, 0}, {0.3, 0.3, 0}, {0.3, -0.3, 0}},
                                                   disk};
    const Vec3 down(0, 0, -1);
    Random rng(7);
    auto unit = [&] {
        Vec3 v(rng.nextDouble() - 0.5, rng.nextDouble() - 0.5, rng.nextDouble() - 0.5);
        return glm::length(v) > 1e-3 ? glm::normalize(v) : Vec3(0, 0, -1);
    };
    for (const auto& poly : lights) {
        const PolygonMoments moments = polygonMoments(triangles(poly));
        CHECK(glm::length(moments.centroid) < 1e-12);
        double diameter = 0, area = 0;
        for (const auto& t : triangles(poly)) area += 0.5 * glm::length(glm::cross(t[1] - t[0], t[2] - t[0]));
        for (const Vec3& v : poly) diameter = std::max(diameter, 2 * glm::length(v));
        double previous = 1;
        for (double k : {2.0, 5.0, 10.0}) {
            double worst = 0;
            int tried = 0;
            for (int i = 0; i < 4000; ++i) {
                Vec3 dir = unit();
                dir.z = -std::abs(dir.z);
                const Vec3 x = k * diameter * dir;
                Vec3 n = unit();
                if (glm::dot(n, -x) < 0) n = -n;
                bool above = x.z < 0;
                for (const Vec3& v : poly) above &= glm::dot(n, v - x) > 0;
                if (!above) continue;
                ++tried;
                const double exact = toPolygon(x, n, poly, down);
                const double scale = area / (kPi * glm::dot(x, x));
                worst = std::max(worst, std::abs(formFactorSecondOrder(x, n, moments, down, area) - exact) / scale);
            }
            INFO("polygon of " << poly.size() << " at " << k << " diameters, " << tried << " points");
            CHECK(tried > 1000);
            CHECK(worst < previous / 10);  // (d/r)⁴: 2 → 5 diameters is ×39, 5 → 10 ×16
            if (k == 5.0) CHECK(worst < 1e-4);
            previous = worst;
        }
    }
    // Behind the polygon, or the polygon facing away: nothing.
    const auto square = polygonMoments(triangles(lights[0]));
    CHECK(formFactorSecondOrder({0, 0, 5}, {0, 0, -1}, square, down, 0.36) == 0.0);
    CHECK(formFactorSecondOrder({0, 0, -5}, {0, 0, -1}, square, down, 0.36) == 0.0);
}

TEST_CASE("the edge angle agrees with atan2 over the whole half turn", "[form_factor]") {
    // Angles from 1e-12 rad to π − 1e-9, on both sides of every table point (k/16) and of
    // π/4 and π/2, as the unit vectors' cross length s and dot product c.
    std::vector<double> angles = {1e-12, 1e-6, 0.01, kPi / 4, kPi / 2, kPi - 1e-3, kPi - 1e-9};
    for (int k = 0; k <= 16; ++k)
        for (double d : {-1e-9, 0.0, 1e-9, 0.5 / 32}) angles.push_back(std::atan(k / 16.0) + d);
    Random rng(7);
    for (int i = 0; i < 10000; ++i) angles.push_back(kPi * rng.nextDouble());
    double worst = 0;
    for (double theta : angles) {
        if (!(theta > 0 && theta < kPi)) continue;
        for (double scale : {1.0, 0.37, 2.9}) {  // unnormalised pairs too
            const double s = scale * std::sin(theta), c = scale * std::cos(theta);
            const double expected = std::atan2(s, c);
            worst = std::max(worst, std::abs(edgeAngle(s, c) - expected) / expected);
        }
    }
    CHECK(worst < 4e-16);
    CHECK(edgeAngle(0.0, 1.0) == 0.0);
    CHECK(edgeAngle(0.0, -1.0) == Approx(kPi));
    CHECK(std::isnan(edgeAngle(std::nan(""), 1.0)));
}
