#include <app/daylight_warnings.h>

#include <scene/polygon.h>

#include <fmt/format.h>

#include <cmath>
#include <limits>

namespace rayrad::app {

namespace {
constexpr int kSide = 8;  ///< kSide² cosine-distributed probe rays per side of an opening

/// The fraction of cosine-distributed rays from c into the half-space of n that meet a
/// surface within `reach` m (infinity: at all).
double coveredFraction(const raytrace::EmbreeScene& embree, const Vec3& c, const Vec3& n, double reach) {
    const auto [t1, t2] = tangentFrame(n);
    int hits = 0;
    for (int a = 0; a < kSide; ++a)
        for (int b = 0; b < kSide; ++b) {
            const double u = (a + 0.5) / kSide, phi = 2 * kPi * (b + 0.5) / kSide, r = std::sqrt(u);
            const Vec3 w = r * std::cos(phi) * t1 + r * std::sin(phi) * t2 + std::sqrt(1 - u) * n;
            const raytrace::Hit h = embree.intersect(c + embree.epsilon() * n, w, 0.0, reach);
            hits += h.found ? 1 : 0;
        }
    return hits / double(kSide * kSide);
}
}  // namespace

std::vector<std::string> daylightWarnings(const scene::Scene& scene, const raytrace::EmbreeScene& embree) {
    std::vector<std::string> out;
    if (!scene.daylight) return out;
    const scene::Daylight& d = *scene.daylight;
    if (d.sunNormalIlluminance > 0 && d.sun && d.sun->altitudeDeg <= 0)
        out.push_back(fmt::format("{}/sun: the sun is below the horizon (altitude {:.2f}°): no direct sun, the sky only",
                                  d.where, d.sun->altitudeDeg));
    bool anyOpening = false;
    for (const auto& g : scene.groups) {
        if (!scene.materials[g.material].isOpening()) continue;
        anyOpening = true;
        for (const auto& poly : g.polygons) {
            std::vector<Vec3> v;
            for (uint32_t k : poly) v.push_back(g.positions[k]);
            Vec3 c(0.0);
            for (const auto& x : v) c += x;
            c /= static_cast<double>(v.size());
            const Vec3 n = scene::polygonNormal(v);
            const double inf = std::numeric_limits<double>::infinity();
            const double inside = coveredFraction(embree, c, n, inf), outside = coveredFraction(embree, c, -n, inf);
            const double behind = coveredFraction(embree, c, -n, std::max(0.05, 1e-3 * scene.diagonal()));
            if (inside < 0.25 && outside > 0.75) {
                out.push_back(fmt::format("{}: the opening at {} faces away from the room ({:.0f} % of the rays from "
                                          "its front meet a surface, {:.0f} % from its back): its front must face "
                                          "the room — is it wound backwards?",
                                          g.where, toString(c), 100 * inside, 100 * outside));
                break;
            }
            if (behind >= 0.75) {
                out.push_back(fmt::format("{}: the opening at {} is covered behind within a few centimetres ({:.0f} % "
                                          "of the rays from its back): the sky can hardly reach it — is a wall "
                                          "without a hole behind it?",
                                          g.where, toString(c), 100 * behind));
                break;
            }
        }
    }
    if (!anyOpening)
        out.push_back(fmt::format("{}: no surface is an opening (a material of type \"opening\"): the sky comes in "
                                  "only through openings, so it lights nothing{}",
                                  d.where, d.hasDirectSun() ? " (the sun still does)" : ""));
    return out;
}

}  // namespace rayrad::app
