// The shooting iteration: energy balance, analytic sphere, determinism.
#include <radiosity/shooting/shooting_solver.h>
#include <radiosity/solution/energy_balance.h>
#include "solved_scene.h"

#include "scene/scene_test_util.h"
#include "test_support.h"

#include <tbb/global_control.h>

#include <cstdio>
#include <fstream>

using namespace rayrad;

namespace {}  // namespace

TEST_CASE("closed box: emitted = absorbed + unshot within 0.5%", "[solver]") {
    std::string json = test::boxScene(R"({"type": "diffuse", "reflectance": [0.8, 0.5, 0.2]})",
                                      R"({"type": "point", "position": [0.3, 0.6, 0.45], "intensity_cd": 100})");
    auto run = test::solve(test::writeTempScene("box", json), {{"radiosity.max_edge", "0.125"}});
    auto b = radiosity::energyBalance(run.scene, run.mesh, run.lighting.solution, run.lighting.lights->emittedFlux());
    INFO("emitted " << b.emitted << " absorbed " << b.absorbed << " unshot " << b.unshot);
    CHECK(run.lighting.solution.converged);
    CHECK(b.emitted == Approx(4 * kPi * 100));
    CHECK(std::abs(b.relativeError()) < 0.005);
}

TEST_CASE("closed sphere: the indirect light is rho/(1-rho) Phi / A", "[solver]") {
    // Inside a true closed diffuse sphere every point sees every other with F = dA / A,
    // so E_ind = ρ/(1−ρ) Φ / A everywhere. The tessellated sphere is a polyhedron: there
    // the point values at the sensors still agree to 1% (gather), and the area-weighted
    // mean over the patches is exactly ρ/(1−ρ) Φ / A for any closed scene of uniform ρ
    // (all flux is eventually absorbed), but single patch values vary by about ±5% with
    // the triangles' depth — measured without clusters — so they are compared with the
    // unclustered solution instead.
    std::string json = R"({"materials": {"m": {"reflectance": 0.5}},
        "objects": [{"type": "sphere", "material": "m", "radius": 1, "subdivisions": 12, "facing": "inward"}],
        "lights": [{"type": "point", "position": [0.2, 0.4, 0.6], "intensity_cd": 100}],
        "sensors": [{"name": "A", "position": [0, 0, 1], "normal": [0, 0, -1]},
                    {"name": "B", "position": [0, -0.70710678, -0.70710678], "normal": [0, 0.70710678, 0.70710678]}],
        "radiosity": {"max_edge": 10, "stop_unshot": 1e-4}})";
    std::string path = test::writeTempScene("sphere", json);
    auto run = test::solve(path);
    REQUIRE(run.lighting.clustering.multiPatchClusters() > 0);
    double area = run.mesh.totalArea();
    double expected = 0.5 / (1 - 0.5) * (4 * kPi * 100) / area;
    for (const auto& s : run.sensors) {
        INFO(s.sensor.name);
        CHECK(luminance(s.value.indirect) == Approx(expected).epsilon(0.01));
    }
    double mean = 0;
    for (size_t i = 0; i < run.mesh.patches.size(); ++i)
        mean += luminance(run.lighting.solution.indirect[i]) * run.mesh.patches[i].area;
    CHECK(mean / area == Approx(expected).epsilon(0.005));

    auto plain = test::solve(path, {{"clusters.enabled", "false"}});
    double worst = 0;
    for (size_t i = 0; i < run.mesh.patches.size(); ++i)
        worst = std::max(worst, std::abs(luminance(run.lighting.solution.indirect[i]) /
                                             luminance(plain.lighting.solution.indirect[i]) -
                                         1));
    INFO("worst patch difference clustered vs unclustered: " << 100 * worst << "%");
    CHECK(worst < 0.02);
}

TEST_CASE("curved receivers keep their light: a closed sphere at a 20 degree normal tolerance", "[solver][clusters]") {
    // Clusters of up to 20° of curvature, the per-shot conservation off so the account
    // shows what the transfers lose. Cluster→cluster onto a curved receiver took the
    // member sum at its centroid, which lies off its surface: −0.31 % of the emitted light
    // went missing. Taken at the receiver's sample patches and carried to the centroid
    // by the point kernel (clusterTransfer): measured +0.025 % (10°: +0.07 %; without
    // clusters +0.08 %).
    std::string json = R"({"materials": {"m": {"reflectance": 0.5}},
        "objects": [{"type": "sphere", "material": "m", "radius": 1, "subdivisions": 12, "facing": "inward"}],
        "lights": [{"type": "point", "position": [0.2, 0.4, 0.6], "intensity_cd": 100}],
        "radiosity": {"max_edge": 10, "stop_unshot": 1e-4, "conserve_energy": false},
        "clusters": {"normal_tolerance_deg": 20}})";
    auto run = test::solve(test::writeTempScene("curved_receivers", json));
    REQUIRE(run.lighting.clustering.multiPatchClusters() > 100);
    auto b = radiosity::energyBalance(run.scene, run.mesh, run.lighting.solution, run.lighting.lights->emittedFlux());
    INFO("emitted " << b.emitted << " absorbed " << b.absorbed << " unshot " << b.unshot << " not accounted "
                    << 100 * b.relativeError() << " %");
    CHECK(std::abs(b.relativeError()) < 0.001);
}

TEST_CASE("the solve is deterministic and independent of the thread count", "[solver]") {
    std::string path = test::sourcePath("scenes/cube/cube.json");
    const std::vector<scene::Override> o = {{"radiosity.max_edge", "2.5"}, {"radiosity.stop_unshot", "0.01"}};
    auto a = test::solve(path, o, false);
    std::optional<test::SolvedScene> b;
    {
        tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
        b.emplace(test::solve(path, o, false));
    }
    REQUIRE(a.lighting.solution.indirect.size() == b->lighting.solution.indirect.size());
    CHECK(a.lighting.solution.shots == b->lighting.solution.shots);
    for (size_t i = 0; i < a.lighting.solution.indirect.size(); ++i)
        REQUIRE(a.lighting.solution.indirect[i] == b->lighting.solution.indirect[i]);
}

TEST_CASE("the solve stops at the first shot that leaves less than stop_unshot of the emitted flux unshot",
          "[solver]") {
    // A dark box (ρ = 0.2): its first reflection is a fifth of the emitted flux, so a stop
    // relative to it (the rule before) would shoot on to a fifth of the unshot flux.
    std::string json = test::boxScene(R"({"type": "diffuse", "reflectance": 0.2})",
                                      R"({"type": "point", "position": [0.3, 0.6, 0.45], "intensity_cd": 100})");
    const std::string path = test::writeTempScene("dark_box", json);
    auto run = test::solve(path, {{"radiosity.max_edge", "0.125"}, {"radiosity.stop_unshot", "0.02"}});
    const auto& s = run.lighting.solution;
    REQUIRE(s.converged);
    CHECK(s.emittedFlux == Approx(4 * kPi * 100));
    CHECK(s.initialUnshotFlux == Approx(0.2 * s.emittedFlux).epsilon(0.01));
    CHECK(s.remainingUnshotFlux <= 0.02 * s.emittedFlux);
    CHECK(s.unshotFraction() == Approx(s.remainingUnshotFlux / s.emittedFlux));
    REQUIRE(s.shots > 1);
    auto before = test::solve(path, {{"radiosity.max_edge", "0.125"},
                                     {"radiosity.stop_unshot", "0.02"},
                                     {"radiosity.max_shots", std::to_string(s.shots - 1)}});
    CHECK_FALSE(before.lighting.solution.converged);
    CHECK(before.lighting.solution.remainingUnshotFlux > 0.02 * s.emittedFlux);
}
