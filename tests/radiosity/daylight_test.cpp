// Daylight through openings against closed forms and quadratures computed here.
#include <app/validate_daylight.h>
#include <radiosity/direct/direct_light.h>
#include <radiosity/mesh/mesher.h>
#include <raytrace/embree_scene.h>
#include <scene/daylight/glazing.h>
#include <scene/scene.h>
#include <scene/scene_parser.h>

#include "test_support.h"

#include <cmath>

using namespace rayrad;

namespace {

/// A 2 × 2 m opening (normal −z, facing a room below it, z up) at height h above the
/// origin, a floor far below, and the sky given as JSON.
scene::Scene roofOpening(double h, const std::string& sky, double transmittance = 1) {
    const std::string json = R"({"materials": {"m": {"reflectance": 0.5},
            "hole": {"type": "opening", "transmittance": )" + std::to_string(transmittance) + R"(}},
        "objects": [{"type": "quad", "material": "m", "vertices": [[-50,-50,-10],[50,-50,-10],[50,50,-10],[-50,50,-10]]},
                    {"type": "quad", "material": "hole", "vertices": [[-1,-1,)" + std::to_string(h) + R"(],[-1,1,)" +
                             std::to_string(h) + R"(],[1,1,)" + std::to_string(h) + R"(],[1,-1,)" + std::to_string(h) +
                             R"(]]}],
        "daylight": {"up": [0, 0, 1], "north": [0, 1, 0], "sky": )" + sky + "}}";
    return scene::buildScene(scene::parseScene(json, "t.json"));
}

struct Setup {
    scene::Scene scene;
    radiosity::PatchMesh mesh;
    std::unique_ptr<raytrace::EmbreeScene> embree;
    std::unique_ptr<radiosity::DirectLight> lights;
    explicit Setup(scene::Scene s) : scene(std::move(s)) {
        mesh = radiosity::premesh(scene, scene.meshing);
        embree = std::make_unique<raytrace::EmbreeScene>(mesh, 1e-5 * scene.diagonal());
        lights = std::make_unique<radiosity::DirectLight>(scene);
    }
    double at(const Vec3& x, const Vec3& n, int samples = 16) const {
        return luminance(lights->illuminance(x, n, *embree, samples, nullptr));
    }
};

/// F from a point to a parallel a × b rectangle one of whose corners lies straight above
/// it at height h (the classic corner formula).
double cornerFormFactor(double a, double b, double h) {
    const double X = a / h, Y = b / h;
    return (X / std::sqrt(1 + X * X) * std::atan(Y / std::sqrt(1 + X * X)) +
            Y / std::sqrt(1 + Y * Y) * std::atan(X / std::sqrt(1 + Y * Y))) /
           (2 * kPi);
}

/// ∫ L(ω) cosθ_x cosθ_y / r² dA over the opening z = h, |x|, |y| ≤ 1 seen from x (normal +z),
/// by the midpoint rule on an n × n grid; L from the direction (unit, z up).
template <class Luminance>
double openingQuadrature(const Vec3& x, double h, Luminance L, int n = 800) {
    double sum = 0;
    const double cell = 2.0 / n;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const Vec3 y(-1 + (i + 0.5) * cell, -1 + (j + 0.5) * cell, h);
            const Vec3 d = y - x;
            const double r2 = glm::dot(d, d), r = std::sqrt(r2);
            sum += L(d / r) * (d.z / r) * (d.z / r) / r2;
        }
    return sum * cell * cell;
}

/// ∫ L(ω) cosθ_x cosθ_y / r² dA over the roof opening z = 3, |x|, |y| ≤ 1, seen from x on a
/// plane facing −x (cosθ_x = −ω_x, 0 behind it), by the midpoint rule on a 1600² grid.
template <class Luminance>
double roofOpeningFacingMinusX(const Vec3& x, Luminance L) {
    const int n = 1600;
    const double cell = 2.0 / n;
    double sum = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const Vec3 d = Vec3(-1 + (i + 0.5) * cell, -1 + (j + 0.5) * cell, 3) - x;
            const double r2 = glm::dot(d, d), r = std::sqrt(r2);
            if (d.x < 0) sum += L(d / r) * (-d.x / r) * (d.z / r) / r2;
        }
    return sum * cell * cell;
}

}  // namespace

TEST_CASE("daylight: a uniform sky through a roof opening gives pi L F", "[daylight]") {
    Setup s(roofOpening(3, R"({"type": "uniform", "zenith_luminance": 1000})"));
    const double F = 4 * cornerFormFactor(1, 1, 3);  // on the axis: four corners
    CHECK(s.at({0, 0, 0}, {0, 0, 1}) == Approx(kPi * 1000 * F).epsilon(1e-9));
    // Off the axis: sums and differences of corner rectangles.
    const double Foff = 2 * (cornerFormFactor(3.5, 1, 3) - cornerFormFactor(1.5, 1, 3));
    CHECK(s.at({2.5, 0, 0}, {0, 0, 1}) == Approx(kPi * 1000 * Foff).epsilon(1e-9));
}

TEST_CASE("daylight: the CIE overcast sky through a roof opening, against a quadrature", "[daylight]") {
    Setup s(roofOpening(3, R"({"type": "cie_overcast", "zenith_luminance": 3000})"));
    auto overcast = [](const Vec3& w) { return 3000 * (1 + 2 * w.z) / 3; };  // Moon & Spencer
    for (const Vec3& x : {Vec3(0, 0, 0), Vec3(2.5, 0, 0), Vec3(1, 4, 1)}) {
        const double reference = openingQuadrature(x, 3, overcast);
        INFO("x = " << toString(x));
        const double e = s.at(x, {0, 0, 1});
        INFO("overcast " << toString(x) << " " << e << " vs " << reference << " " << (e / reference - 1));
        CHECK(e == Approx(reference).epsilon(5e-3));
    }
}

TEST_CASE("daylight: a glazed opening seen from beside its edge, against a quadrature", "[daylight]") {
    // Points on a plane perpendicular to the opening, as on a window's reveal: the light
    // comes in at grazing angles, where the glazing passes little.
    Setup s(roofOpening(3, R"({"type": "cie_overcast", "zenith_luminance": 3000})", 0.8));
    auto glazed = [](const Vec3& w) {
        return 3000 * (1 + 2 * w.z) / 3 * scene::glazingTransmittance(0.8, w.z);  // the opening's normal is −z
    };
    for (double depth : {0.5, 0.1, 0.02}) {
        const Vec3 x(1.0, 0.0, 3 - depth);  // on the plane x = 1 through the opening's edge, facing −x
        const double reference = roofOpeningFacingMinusX(x, glazed);
        const double e = s.at(x, {-1, 0, 0});
        INFO("reveal depth " << depth << ": " << e << " vs " << reference << " " << (e / reference - 1));
        CHECK(e == Approx(reference).epsilon(5e-3));
    }
}

TEST_CASE("daylight: the sky seen through an opening in a mirror", "[daylight]") {
    // A clear sky with the sun in the east, so a mirror's reflection changes which part of
    // the sky is seen. A large vertical mirror (x = 1.5, facing −x, reflectance 0.9) beside
    // the roof opening: what its image of the opening sends to a point facing the mirror
    // is 0.9 × what the real opening sends to the mirrored point facing back, which a
    // quadrature over the opening gives.
    const std::string sky = R"({"type": "cie_clear", "zenith_luminance": 5000}, "sun": {"altitude": 30, "azimuth": 90})";
    const std::string withMirror = R"({"materials": {"m": {"reflectance": 0.5}, "hole": {"type": "opening"},
            "mirror": {"type": "mirror", "specular_reflectance": 0.9}},
        "objects": [{"type": "quad", "material": "m", "vertices": [[-50,-50,-10],[50,-50,-10],[50,50,-10],[-50,50,-10]]},
                    {"type": "quad", "material": "hole", "vertices": [[-1,-1,3],[-1,1,3],[1,1,3],[1,-1,3]]},
                    {"type": "quad", "material": "mirror", "vertices": [[1.5,-20,-9],[1.5,-20,20],[1.5,20,20],[1.5,20,-9]]}],
        "daylight": {"up": [0, 0, 1], "north": [0, 1, 0], "sky": )" + sky + "}}";
    Setup mirrored(scene::buildScene(scene::parseScene(withMirror, "t.json")));
    Setup plain(roofOpening(3, sky));
    for (const Vec3& x : {Vec3(0.5, 0, 0), Vec3(1.2, 0.7, 1.5)}) {
        const Vec3 image(3.0 - x.x, x.y, x.z);  // x mirrored in the plane x = 1.5, facing −x
        const double reference =
            0.9 * roofOpeningFacingMinusX(image, [&](const Vec3& w) { return plain.scene.daylight->luminance(w); });
        const double viaMirror = mirrored.at(x, {1, 0, 0}) - plain.at(x, {1, 0, 0});
        INFO("at " << x.x << ", " << x.y << ", " << x.z << ": " << viaMirror << " vs " << reference);
        CHECK(viaMirror == Approx(reference).epsilon(5e-3));
    }
}

TEST_CASE("daylight: validate daylight passes every check", "[daylight]") {
    CHECK(app::validateDaylight() == 0);
}

TEST_CASE("daylight: bad daylight input is refused with its place", "[daylight]") {
    auto refused = [](const std::string& daylight, const std::string& material = R"({"type": "opening"})") {
        const std::string json = R"({"materials": {"m": {"reflectance": 0.5}, "hole": )" + material + R"(},
            "objects": [{"type": "quad", "material": "m", "vertices": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]]}],
            "daylight": )" + daylight + "}";
        try {
            scene::parseScene(json, "t.json");
        } catch (const std::exception& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    const std::string sky = R"("sky": {"type": "cie_overcast", "zenith_luminance": 1000})";
    CHECK_THAT(refused("{" + sky + R"(, "sun": {"latitude": 95, "longitude": 0, "utc_offset": 0, "date": "2026-06-21", "time": "12:00"}})"),
               Catch::Contains("/daylight/sun/latitude") && Catch::Contains("[−90°, 90°]"));
    CHECK_THAT(refused("{" + sky + R"(, "sun": {"latitude": 50, "longitude": 0, "utc_offset": 0, "date": "2026-02-30", "time": "12:00"}})"),
               Catch::Contains("/daylight/sun/date") && Catch::Contains("not a date"));
    CHECK_THAT(refused(R"({"sky": {"type": "cie_overcast"}})"),
               Catch::Contains("/daylight/sky") && Catch::Contains("exactly one scale"));
    CHECK_THAT(refused(R"({"sky": {"type": "cie_clear", "zenith_luminance": 1000}})"),
               Catch::Contains("/daylight/sun") && Catch::Contains("brighter toward the sun"));
    CHECK_THAT(refused("{" + sky + "}", R"({"type": "opening", "transmittance": 1.5})"),
               Catch::Contains("/materials/hole/transmittance") && Catch::Contains("(0, 1]"));
    CHECK(refused("{" + sky + "}").empty());
}

TEST_CASE("daylight: clear glass passes its normal transmittance at 0 degrees and less at grazing angles",
          "[daylight]") {
    CHECK(scene::glazingTransmittance(0.8, 1.0) == Approx(0.8).epsilon(1e-12));
    CHECK(scene::glazingTransmittance(1.0, 0.1) == 1.0);  // an open hole
    // A single clear pane: 0.85–0.97 of its normal value at 60° (reflection and a longer path), 0 at 90°.
    const double ratio60 = scene::glazingTransmittance(0.8, 0.5) / 0.8;
    CHECK(ratio60 > 0.85);
    CHECK(ratio60 < 0.97);
    CHECK(scene::glazingTransmittance(0.8, 1e-6) < 0.01);
}
