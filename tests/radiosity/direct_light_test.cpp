// Direct light from point, spot and area lights against closed forms; mesh import.
#include <radiosity/direct/direct_light.h>
#include <radiosity/mesh/mesher.h>
#include <raytrace/embree_scene.h>
#include <scene/scene.h>
#include <scene/scene_parser.h>

#include "test_support.h"

#include <cmath>

using namespace rayrad;

namespace {

/// A scene with a floor quad far below everything (so visibility is trivially clear).
scene::Scene withLights(const std::string& lights, const std::string& extraObjects = "",
                        const std::string& extraMaterials = "") {
    std::string json = R"({"materials": {"m": {"reflectance": 0.5})" + extraMaterials + R"(},
        "objects": [{"type": "quad", "material": "m", "vertices": [[-50,-50,-10],[50,-50,-10],[50,50,-10],[-50,50,-10]]})" +
                       extraObjects + R"(],
        "lights": [)" + lights +
                       "]}";
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
    double at(const Vec3& x, const Vec3& n, int samples = 64) const {
        return luminance(lights->illuminance(x, n, *embree, samples, nullptr));
    }
};

}  // namespace

TEST_CASE("point light: E = I cos(theta) / d^2", "[direct]") {
    Setup s(withLights(R"({"type": "point", "position": [0, 0, 3], "intensity_cd": 900})"));
    CHECK(s.at({0, 0, 0}, {0, 0, 1}) == Approx(100.0));
    CHECK(s.at({4, 0, 0}, {0, 0, 1}) == Approx(900.0 * (3.0 / 5.0) / 25.0));
    CHECK(s.at({0, 0, 0}, {0, 0, -1}) == 0.0);  // facing away
    CHECK(s.lights->emittedFlux() == Approx(4 * kPi * 900));
}

TEST_CASE("spot light: full inside the inner cone, zero outside the outer, flux by integration", "[direct]") {
    Setup s(withLights(R"({"type": "spot", "position": [0, 0, 2], "direction": [0, 0, -1], "intensity_cd": 400,
                          "inner_angle_deg": 20, "outer_angle_deg": 30})"));
    CHECK(s.at({0, 0, 0}, {0, 0, 1}) == Approx(100.0));  // on the axis: I / d²
    double inside = 2 * std::tan(glm::radians(15.0));
    double d2 = 4 + inside * inside;
    CHECK(s.at({inside, 0, 0}, {0, 0, 1}) == Approx(400.0 * (2 / std::sqrt(d2)) / d2));
    CHECK(s.at({2 * std::tan(glm::radians(31.0)), 0, 0}, {0, 0, 1}) == 0.0);
    // Φ = 2π ∫ I(θ) sinθ dθ: between the flux of a 20° and a 30° hard-edged cone.
    double flux = s.lights->emittedFlux();
    CHECK(flux > 2 * kPi * 400 * (1 - std::cos(glm::radians(20.0))));
    CHECK(flux < 2 * kPi * 400 * (1 - std::cos(glm::radians(30.0))));
}

TEST_CASE("area light: a square emitter above a point gives pi L F (catalogue B-1)", "[direct]") {
    // Emitter [0,1]×[0,1] at z = 1 facing down, L = 1000 cd/m²; receiver at the origin.
    std::string emitter = R"(, {"type": "quad", "material": "lamp", "vertices": [[0,0,1],[0,1,1],[1,1,1],[1,0,1]]})";
    std::string lamp = R"(, "lamp": {"type": "emissive", "luminance_cd_m2": 1000})";
    Setup s(withLights(R"({"type": "point", "position": [0, 0, -20], "intensity_cd": 1e-9})", emitter, lamp));
    double A = 1.0, B = 1.0;
    double F = (A / std::sqrt(1 + A * A) * std::atan(B / std::sqrt(1 + A * A)) +
                B / std::sqrt(1 + B * B) * std::atan(A / std::sqrt(1 + B * B))) /
               (2 * kPi);
    CHECK(s.at({0, 0, 0}, {0, 0, 1}) == Approx(kPi * 1000 * F).epsilon(1e-9));
    CHECK(s.lights->emittedFlux() == Approx(kPi * 1000 * 1.0 + 4 * kPi * 1e-9));  // Φ = π L A
}

TEST_CASE("area light: an occluder halfway casts a shadow", "[direct]") {
    std::string emitter =
        R"(, {"type": "quad", "material": "lamp", "vertices": [[-0.1,-0.1,2],[-0.1,0.1,2],[0.1,0.1,2],[0.1,-0.1,2]]},
                              {"type": "quad", "material": "m", "vertices": [[-1,-1,1],[1,-1,1],[1,1,1],[-1,1,1]]})";
    std::string lamp = R"(, "lamp": {"type": "emissive", "luminance_cd_m2": 1000})";
    Setup s(withLights(R"({"type": "point", "position": [0, 0, -20], "intensity_cd": 1e-9})", emitter, lamp));
    CHECK(s.at({0, 0, 0}, {0, 0, 1}) < 1e-6);
    CHECK(s.at({5, 0, 0}, {0, 0, 1}) > 0.0);  // sees the lamp past the occluder's edge
}

TEST_CASE("OBJ meshes load through assimp with their transform", "[scene]") {
    std::string json = R"({"materials": {"m": {"reflectance": 0.5}},
        "objects": [{"type": "mesh", "material": "m", "file": "tetrahedron.obj",
                     "transform": {"scale": 2, "translate": [10, 0, 0]}}],
        "lights": [{"type": "point", "position": [0, 0, 5], "intensity_cd": 1}]})";
    auto s = scene::buildScene(scene::parseScene(json, test::sourcePath("tests/data/scene.json")));
    REQUIRE(s.groups.size() == 1);
    CHECK(s.groups[0].polygons.size() == 4);
    CHECK(s.boundsMin == Vec3(10, 0, 0));
    CHECK(s.boundsMax == Vec3(12, 2, 2));
    auto mesh = radiosity::premesh(s, s.meshing);
    // Closed and outward: the normals point away from the centroid.
    Vec3 c(10.5, 0.5, 0.5);
    for (const auto& p : mesh.patches) REQUIRE(glm::dot(p.normal, p.centroid - c) > 0);
    CHECK(mesh.totalArea() == Approx(4 * (1.5 + std::sqrt(3.0) / 2)));
}

namespace {
/// Counts the shadow rays it answers (all visible: an empty scene's answer).
struct CountingVisibility : Visibility {
    mutable size_t rays = 0;
    bool visible(const Vec3&, const Vec3&) const override { return ++rays, true; }
};
/// Blocks every ray to a point above the plane z = height (a ceiling of lights hidden).
struct BlockedAbove : Visibility {
    double height;
    explicit BlockedAbove(double h) : height(h) {}
    bool visible(const Vec3& from, const Vec3& to) const override { return std::max(from.z, to.z) < height; }
};
}  // namespace

TEST_CASE("adaptive shadow testing: the strong lights tested, the weak ones estimated, within the threshold",
          "[direct]") {
    // One bright light above the point and 60 weak ones far away (3 of every 4 points
    // under a 'ceiling' that blocks them at z > 5).
    std::string lights = R"({"type": "point", "position": [0, 0, 2], "intensity_cd": 4000})";
    for (int k = 0; k < 60; ++k)
        lights += R"(, {"type": "point", "position": [)" + std::to_string(10 + k % 10) + ", " + std::to_string(k / 10) +
                  ", " + (k % 4 == 0 ? "4" : "6") + R"(], "intensity_cd": 100})";
    Setup s(withLights(lights));
    const Vec3 x(0, 0, 0), n(0, 0, 1);

    // Threshold 0 is the exact sum, ray for ray.
    CountingVisibility all, some;
    const Rgb exact = s.lights->illuminance(x, n, all, 16, nullptr);
    CHECK(s.lights->illuminanceForDisplay(x, n, all, 16, nullptr, 0.0) == exact);
    CHECK(all.rays == 2 * 61);

    // 0.02: fewer rays, and what the untested lights bring is estimated, not dropped.
    const Rgb adaptive = s.lights->illuminanceForDisplay(x, n, some, 16, nullptr, 0.02);
    CHECK(some.rays < 61);
    CHECK(luminance(adaptive) == Approx(luminance(exact)).epsilon(1e-12));  // nothing occluded: the estimate is exact

    // With the far lights mostly hidden the estimate errs, by less than the threshold.
    BlockedAbove ceiling(5.0);
    const double truth = luminance(s.lights->illuminance(x, n, ceiling, 16, nullptr));
    const double estimate = luminance(s.lights->illuminanceForDisplay(x, n, ceiling, 16, nullptr, 0.02));
    CHECK(std::abs(estimate / truth - 1) < 0.02);
    CHECK(estimate != truth);  // it did estimate (the test would prove nothing otherwise)

    // Under a desk every light is blocked: with nothing found, each one was tested. What
    // the point receives besides (indirect light) bounds the error too, so fewer are, and
    // the estimate stays within the threshold of all the point receives.
    struct CountingBlocked : BlockedAbove {
        mutable size_t rays = 0;
        using BlockedAbove::BlockedAbove;
        bool visible(const Vec3& from, const Vec3& to) const override {
            return ++rays, BlockedAbove::visible(from, to);
        }
    };
    CountingBlocked alone(1.0), withIndirect(1.0);
    const double dark = luminance(s.lights->illuminanceForDisplay(x, n, alone, 16, nullptr, 0.02));
    CHECK(alone.rays == 61);
    CHECK(dark == 0);
    const double received = 50;  // lx of indirect light
    const double under = luminance(s.lights->illuminanceForDisplay(x, n, withIndirect, 16, nullptr, 0.02, received));
    CHECK(withIndirect.rays < alone.rays);
    CHECK(withIndirect.rays > 1);  // the bright light alone does not settle it
    CHECK(std::abs(under - 0) <= 0.02 * (0 + received));
}

TEST_CASE("a pixel's samples on one patch share the far lights' shadow rays", "[direct]") {
    // A dim emitter just above the point and 24 small bright ones 6–11 m away (far: beyond
    // five of their diameters), all facing down.
    auto square = [](double x, double y, double z, double half) {
        auto v = [&](double a, double b) {
            return "[" + std::to_string(a) + "," + std::to_string(b) + "," + std::to_string(z) + "]";
        };
        return "[" + v(x - half, y - half) + "," + v(x - half, y + half) + "," + v(x + half, y + half) + "," +
               v(x + half, y - half) + "]";
    };
    std::string emitters = R"(, {"type": "quad", "material": "dim", "vertices": )" + square(0, 0, 1, 0.2) + "}";
    for (int k = 0; k < 24; ++k)
        emitters += R"(, {"type": "quad", "material": "bright", "vertices": )" +
                    square(6 + 0.2 * k, (k % 2 ? 1 : -1) * 0.5 * k, 3, 0.1) + "}";
    const std::string materials = R"(, "dim": {"type": "emissive", "luminance_cd_m2": 300},
                                       "bright": {"type": "emissive", "luminance_cd_m2": 20000})";
    Setup s(withLights(R"({"type": "point", "position": [0, 0, -20], "intensity_cd": 1e-9})", emitters, materials));
    const Vec3 n(0, 0, 1), x1(0, 0, 0), x2(0.002, 0.001, 0);  // two samples a pixel's width apart

    // The first sample fills the memo; the second, on the same patch, traces the near
    // light's rays alone and agrees with tracing its own to well under the threshold.
    CountingVisibility first, second, own;
    radiosity::PixelLightMemo pixel;
    const Rgb e1 = s.lights->illuminanceForDisplay(x1, n, first, 16, nullptr, 0.02, 0, &pixel, 7);
    REQUIRE(!pixel.far.empty());
    CHECK(pixel.retested.size() == 1);  // the near emitter
    CHECK(luminance(e1) == Approx(luminance(s.lights->illuminanceForDisplay(x1, n, own, 16, nullptr, 0.02))));
    const Rgb shared = s.lights->illuminanceForDisplay(x2, n, second, 16, nullptr, 0.02, 0, &pixel, 7);
    CountingVisibility alone;
    const Rgb traced = s.lights->illuminanceForDisplay(x2, n, alone, 16, nullptr, 0.02);
    CHECK(second.rays < first.rays);
    CHECK(second.rays == first.rays - pixel.far.size());  // one ray per far light, 6 m and more away
    CHECK(luminance(shared) == Approx(luminance(traced)).epsilon(1e-3));

    // Far lights hidden at the first sample stay hidden for the second (a soft shadow's
    // value at a pixel's scale), and near ones are tested again.
    BlockedAbove ceiling(2.0);
    radiosity::PixelLightMemo hidden;
    s.lights->illuminanceForDisplay(x1, n, ceiling, 16, nullptr, 0.02, 0, &hidden, 7);
    const double dimOnly = luminance(s.lights->illuminanceForDisplay(x2, n, ceiling, 16, nullptr, 0.02, 0, &hidden, 7));
    CHECK(dimOnly ==
          Approx(luminance(s.lights->illuminanceForDisplay(x2, n, ceiling, 16, nullptr, 0.0))).epsilon(0.02));

    // Another patch starts the memo afresh.
    CountingVisibility other;
    s.lights->illuminanceForDisplay(x2, n, other, 16, nullptr, 0.02, 0, &pixel, 8);
    CHECK(other.rays == alone.rays);
    CHECK(pixel.patch == 8);
}
