// The side-lit office under the CIE overcast sky against a small Monte Carlo path tracer
// written here: daylight factors at three points on the room's axis.
#include <app/pipeline.h>
#include <radiosity/radiosity.h>
#include <scene/daylight/glazing.h>
#include <scene/polygon.h>
#include <scene/scene.h>
#include <scene/scene_parser.h>

#include "test_support.h"

#include <cmath>
#include <optional>
#include <random>
#include <vector>

using namespace rayrad;

namespace {

struct Triangle {
    Vec3 a, b, c, normal;
    double rho = 0;  ///< diffuse reflectance (luminance)
    bool opening = false;
    double tau = 1;  ///< an opening's normal transmittance
};

/// Möller–Trumbore: distance along the unit d from o to the triangle, or nothing.
std::optional<double> hit(const Triangle& t, const Vec3& o, const Vec3& d) {
    const Vec3 e1 = t.b - t.a, e2 = t.c - t.a, p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    if (std::abs(det) < 1e-14) return std::nullopt;
    const Vec3 s = o - t.a;
    const double u = glm::dot(s, p) / det;
    if (u < 0 || u > 1) return std::nullopt;
    const Vec3 q = glm::cross(s, e1);
    const double v = glm::dot(d, q) / det;
    if (v < 0 || u + v > 1) return std::nullopt;
    const double dist = glm::dot(e2, q) / det;
    return dist > 1e-9 ? std::optional<double>(dist) : std::nullopt;
}

struct Office {
    std::vector<Triangle> triangles;
    double zenith = 0, ground = 0, horizontal = 0;  ///< L_z, the ground's luminance (cd/m²), E_dh (lx)
    Vec3 up{0, 1, 0};

    /// The sky (traditional overcast) or the ground along the unit direction w.
    double outdoors(const Vec3& w) const {
        const double c = glm::dot(w, up);
        return c >= 0 ? zenith * (1 + 2 * c) / 3 : ground;
    }

    /// Radiance arriving at o from direction d (unit), by path tracing.
    double radiance(Vec3 o, Vec3 d, std::mt19937_64& rng) const {
        std::uniform_real_distribution<double> uni(0, 1);
        double throughput = 1;
        for (int bounce = 0; bounce < 200; ++bounce) {
            double nearest = 1e300;
            const Triangle* surface = nullptr;
            for (const auto& t : triangles)
                if (!t.opening)
                    if (auto dist = hit(t, o, d); dist && *dist < nearest) nearest = *dist, surface = &t;
            // An opening crossed before the nearest surface: the ray leaves to the sky.
            for (const auto& t : triangles)
                if (t.opening)
                    if (auto dist = hit(t, o, d); dist && *dist < nearest)
                        return throughput * outdoors(d) *
                               scene::glazingTransmittance(t.tau, std::abs(glm::dot(d, t.normal)));
            if (!surface) return throughput * outdoors(d);
            if (glm::dot(surface->normal, d) >= 0) return 0;  // the back of a one-sided surface
            // Diffuse: continue with ρ, Russian roulette past a few bounces.
            throughput *= surface->rho;
            if (bounce > 3) {
                const double keep = std::min(0.9, surface->rho);
                if (uni(rng) > keep) return 0;
                throughput /= keep;
            }
            o = o + nearest * d;
            const auto [t1, t2] = tangentFrame(surface->normal);
            const double u = uni(rng), phi = 2 * kPi * uni(rng), r = std::sqrt(u);
            d = r * std::cos(phi) * t1 + r * std::sin(phi) * t2 + std::sqrt(1 - u) * surface->normal;
            o += 1e-7 * surface->normal;
        }
        return 0;
    }

    /// E at x (normal n), lx: π × the mean radiance of cosine-distributed paths.
    double illuminance(const Vec3& x, const Vec3& n, int paths, uint64_t seed) const {
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> uni(0, 1);
        const auto [t1, t2] = tangentFrame(n);
        double sum = 0;
        for (int i = 0; i < paths; ++i) {
            const double u = uni(rng), phi = 2 * kPi * uni(rng), r = std::sqrt(u);
            const Vec3 d = r * std::cos(phi) * t1 + r * std::sin(phi) * t2 + std::sqrt(1 - u) * n;
            sum += radiance(x, d, rng);
        }
        return kPi * sum / paths;
    }
};

}  // namespace

TEST_CASE("daylight: the office's daylight factors against a path tracer", "[daylight]") {
    const std::string file = test::sourcePath("scenes/daylight-office/daylight-office.json");
    const scene::Scene built = scene::buildScene(scene::loadScene(file, {}));
    REQUIRE(built.daylight);
    Office office;
    office.horizontal = built.daylight->skyHorizontalIlluminance;
    office.zenith = office.horizontal / (7 * kPi / 9);  // E_dh = 7π/9 L_z
    office.ground = built.daylight->groundReflectance * office.horizontal / kPi;
    office.up = built.daylight->up;
    for (const auto& g : built.groups) {
        const auto& m = built.materials[g.material];
        for (const auto& poly : g.polygons) {
            std::vector<Vec3> v;
            for (uint32_t i : poly) v.push_back(g.positions[i]);
            const Vec3 n = scene::polygonNormal(v);
            for (size_t k = 1; k + 1 < v.size(); ++k)
                office.triangles.push_back(
                    {v[0], v[k], v[k + 1], n, luminance(m.reflectance), m.isOpening(), m.transmittance});
        }
    }
    app::PipelineOptions options;
    options.quiet = true;
    app::PipelineRun run = app::runPipeline(file, options);
    REQUIRE(run.sensors.size() >= 3);
    // The account closes: what came in = absorbed + left again (+ unshot).
    const auto balance = app::energyBalanceOf(run);
    CHECK(std::abs(balance.relativeError()) < 0.01);
    CHECK(balance.leftThroughOpenings > 0);
    for (size_t i = 0; i < 3; ++i) {
        const auto& s = run.sensors[i];
        const double reference =
            100 * office.illuminance(s.sensor.position, s.sensor.normal, 200000, 7 + i) / office.horizontal;
        REQUIRE(s.daylightFactor);
        INFO(s.sensor.name << ": DF " << *s.daylightFactor << " %, path tracer " << reference << " %, "
                           << 100 * (*s.daylightFactor / reference - 1) << " %");
        CHECK(*s.daylightFactor == Approx(reference).epsilon(0.02));
    }
}
