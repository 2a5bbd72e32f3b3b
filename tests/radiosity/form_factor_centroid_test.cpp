// The form factor's centroid (form_factor_centroid.h) against a fine graded subdivision:
// each small piece's Lambert form factor at its area centroid.
#include <radiosity/form_factors/form_factor_centroid.h>

#include <radiosity/form_factors/form_factor.h>

#include "test_support.h"

#include <algorithm>
#include <array>
#include <cmath>

using namespace rayrad;
using namespace rayrad::radiosity;

namespace {

struct Moment {
    double F = 0;
    Vec3 first{0.0};  ///< Σ F_i c_i
};

/// The triangle split toward x while closer than `ratio` of its pieces' sizes (at most
/// `depth` times): Σ F_i and Σ F_i c_i over the pieces, c_i the area centroid.
void reference(const Vec3& x, const Vec3& n, const std::array<Vec3, 3>& t, const Vec3& normal, int depth, Moment& m) {
    constexpr double ratio = 48;
    const Vec3 c = (t[0] + t[1] + t[2]) / 3.0;
    const double size = std::max({glm::length(t[1] - t[0]), glm::length(t[2] - t[1]), glm::length(t[0] - t[2])});
    if (depth > 0 && glm::length(c - x) < ratio * size) {
        const Vec3 a = 0.5 * (t[0] + t[1]), b = 0.5 * (t[1] + t[2]), d = 0.5 * (t[2] + t[0]);
        for (const auto& child : {std::array<Vec3, 3>{t[0], a, d}, std::array<Vec3, 3>{a, t[1], b},
                                  std::array<Vec3, 3>{d, b, t[2]}, std::array<Vec3, 3>{a, b, d}})
            reference(x, n, child, normal, depth - 1, m);
        return;
    }
    const double F = formFactorToPolygon(x, n, t.data(), 3, normal);
    m.F += F;
    m.first += F * c;
}

struct Case {
    const char* what;
    Vec3 x, n;
    std::array<Vec3, 3> t;
};

}  // namespace

TEST_CASE("the form factor's centroid agrees with a fine subdivision, and a linear luminance gives pi F L(c_F)",
          "[form_factor]") {
    const Vec3 down(0, 0, -1), up(0, 0, 1);
    const Case cases[] = {
        {"floor point under a ceiling triangle", {0.2, 0.3, 0}, up, {Vec3(0, 0, 1), Vec3(0, 1, 1), Vec3(1, 0, 1)}},
        {"floor point, the foot outside", {1.5, -0.4, 0}, up, {Vec3(0, 0, 0.6), Vec3(0, 1, 0.6), Vec3(1, 0, 0.6)}},
        {"floor point 0.3 from a wall", {0.3, 0.4, 0}, up, {Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(0, 1, 0)}},
        {"floor point 1 cm from a wall", {0.01, 0.4, 0}, up, {Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(0, 1, 0)}},
        {"floor point 0.1 mm from a wall", {1e-4, 0.2, 0}, up, {Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(0, 1, 0)}},
        {"a tilted receiver that sees part of the triangle",
         {0.2, 0.2, 0.5},
         glm::normalize(Vec3(1, 0.3, 0.2)),
         {Vec3(0, 0, 1), Vec3(0, 1, 1), Vec3(1, 0, 1)}},
        {"a point beside a wall's edge, 5 mm off",
         {0.005, 1.0, 0.3},
         glm::normalize(Vec3(1, 0, 0.4)),
         {Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(0, 1, 0)}},
    };
    for (const Case& c : cases) {
        INFO(c.what);
        const Vec3 normal = glm::normalize(glm::cross(c.t[1] - c.t[0], c.t[2] - c.t[0]));
        const Vec3 facing = glm::dot(c.x - c.t[0], normal) > 0 ? normal : -normal;
        std::array<Vec3, 3> t = c.t;
        if (facing != normal) std::swap(t[1], t[2]);  // the order does not matter to either
        const FormFactorCentroid got = formFactorCentroid(c.x, c.n, t.data(), 3, facing);
        Moment ref;
        reference(c.x, c.n, t, facing, 18, ref);
        REQUIRE(ref.F > 0);
        const Vec3 expected = ref.first / ref.F;
        CHECK(got.F == Approx(ref.F).epsilon(1e-9));
        CHECK(glm::length(got.centroid - expected) < 2e-4);  // of a 1 m triangle
        // A luminance linear over the triangle: π F L(c_F) against the pieces' sum.
        const double L[3] = {1.0, 3.0, 0.5};
        const Vec3 w = barycentric(t[0], t[1], t[2], got.centroid), we = barycentric(t[0], t[1], t[2], expected);
        const double E = kPi * got.F * (w[0] * L[0] + w[1] * L[1] + w[2] * L[2]);
        const double Eref = kPi * ref.F * (we[0] * L[0] + we[1] * L[1] + we[2] * L[2]);
        CHECK(E == Approx(Eref).epsilon(3e-4));
        for (int k = 0; k < 3; ++k) CHECK(w[k] > -1e-9);  // inside the triangle
    }
}
