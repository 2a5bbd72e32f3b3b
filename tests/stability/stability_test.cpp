// Stiff and extreme cases: near-white rooms, exact energy
// accounting, millimetres and kilometres, lights touching walls, broken geometry,
// thousands of lights. Run with `ctest -L stability`; also part of the default run.
#include <app/pipeline.h>
#include <radiosity/shooting/shooting_solver.h>
#include <radiosity/solution/energy_balance.h>

#include "pipeline_test_util.h"
#include "test_support.h"

#include <fmt/format.h>

#include <cmath>
#include <fstream>

using namespace rayrad;
using test::quiet;

namespace {

bool allFinite(const app::PipelineRun& run) {
    for (const auto& v : run.lighting.solution.indirect)
        if (!isFinite(v)) return false;
    for (const auto& s : run.sensors)
        if (!isFinite(s.value.direct) || !isFinite(s.value.indirect)) return false;
    return true;
}

double notAccounted(const app::PipelineRun& run) {
    return app::energyBalanceOf(run).relativeError();
}

/// A closed box room w × h × d (metres) of reflectance rho with a point light, scaled by s.
std::string boxRoom(double s, double rho, double intensity, const std::string& extraObjects = "",
                    const std::string& lights = "") {
    return fmt::format(R"({{"materials": {{"m": {{"reflectance": {rho}}}}},
        "objects": [{{"type": "box", "material": "m", "min": [0, 0, 0], "max": [{a}, {b}, {c}], "facing": "inward"}}{extra}],
        "lights": [{{"type": "point", "position": [{lx}, {ly}, {lz}], "intensity_cd": {i}}}{lights}],
        "sensors": [{{"name": "floor", "position": [{f1}, 0, {f2}], "normal": [0, 1, 0]}},
                    {{"name": "wall", "position": [0, {w1}, {w2}], "normal": [1, 0, 0]}},
                    {{"name": "corner", "position": [{a}, {b}, {c}], "normal": [-0.57735, -0.57735, -0.57735]}}],
        "radiosity": {{"max_edge": {e}}}}})",
                       fmt::arg("rho", rho), fmt::arg("a", 4 * s), fmt::arg("b", 3 * s), fmt::arg("c", 5 * s),
                       fmt::arg("extra", extraObjects), fmt::arg("lx", 1.3 * s), fmt::arg("ly", 2.1 * s),
                       fmt::arg("lz", 1.7 * s), fmt::arg("i", intensity), fmt::arg("lights", lights),
                       fmt::arg("f1", 2.2 * s), fmt::arg("f2", 3.1 * s), fmt::arg("w1", 1.4 * s),
                       fmt::arg("w2", 2.6 * s), fmt::arg("e", 0.5 * s));
}

}  // namespace

TEST_CASE("stiff closed sphere: rho 0.9 / 0.99 / 0.999 within 1 % at three points, energy to 0.1 %", "[stability]") {
    double rho = GENERATE(0.9, 0.99, 0.999);
    // E_ind = ρ/(1−ρ) Φ / A everywhere, A the polyhedron's area; 10 800 patches.
    std::string json = test::closedSphereScene(rho, 30, R"("max_edge": 10)");
    auto run = app::runPipeline(test::writeTempScene(fmt::format("stiff_sphere_{}", rho), json), quiet());
    REQUIRE(run.mesh.patches.size() >= 5000);
    REQUIRE(run.lighting.clustering.multiPatchClusters() > 0);
    REQUIRE(allFinite(run));
    CHECK(run.lighting.solution.converged);
    CHECK(run.lighting.shooting.conserving);
    double expected = rho / (1 - rho) * 4 * kPi * 100 / run.mesh.totalArea();
    for (const auto& s : run.sensors) {
        INFO("rho " << rho << " sensor " << s.sensor.name << " gathered " << luminance(s.value.indirect) << " expected "
                    << expected << " shots " << run.lighting.solution.shots);
        CHECK(luminance(s.value.indirect) == Approx(expected).epsilon(0.01));
    }
    CHECK(std::abs(notAccounted(run)) < 1e-3);
}

TEST_CASE("energy accounting in closed scenes: emitted = absorbed + unshot within 0.1 %", "[stability]") {
    SECTION("the cube, clusters and corrections on") {
        auto run = app::runPipeline(test::sourcePath("scenes/cube/cube.json"),
                                    quiet({{"radiosity.max_edge", "0.5"}, {"clusters.max_illuminance_step_lx", "20"}}));
        REQUIRE(run.lighting.shooting.corrections > 0);
        CHECK(run.lighting.shooting.conserving);
        CHECK(std::abs(notAccounted(run)) < 1e-3);
    }
    SECTION("a coloured room with a block, three channels") {
        std::string json =
            boxRoom(1, 0.6, 100, R"(, {"type": "box", "material": "red", "min": [1, 0, 1], "max": [2, 1, 2]})");
        json.replace(json.find("\"m\": {"), 0, R"("red": {"reflectance": [0.7, 0.2, 0.1]}, )");
        auto run = app::runPipeline(test::writeTempScene("energy_room", json), quiet());
        REQUIRE_FALSE(run.lighting.singleChannel);
        CHECK(run.lighting.shooting.conserving);
        // The block's shadow crosses 0.5 m floor patches (the direct pass samples those
        // more densely), and floor patches run under the block (their shots lose half
        // their light into it, and conservation puts it back).
        auto b = app::energyBalanceOf(run);
        INFO("direct pass " << 100 * b.directError() << " %, secondary " << 100 * b.secondaryError() << " %");
        CHECK(std::abs(b.directError()) < 1e-3);
        CHECK(std::abs(b.secondaryError()) < 1e-3);
        CHECK(std::abs(b.relativeError()) < 1e-3);
    }
}

TEST_CASE("energy accounting with a mirror: what the mirror absorbs is booked", "[stability]") {
    // The mirror room: spots aimed at a Ks = 0.9 mirror hung 1 cm in front of a wall. The
    // images deliver Ks of what reaches the mirror; the rest, and what the wall behind
    // sends into the mirror's back, is booked as absorbed by the mirror.
    auto run = app::runPipeline(test::sourcePath("scenes/mirror_room/mirror_room.json"), quiet());
    CHECK(run.lighting.shooting.conserving);
    auto b = app::energyBalanceOf(run);
    INFO("mirrors " << b.mirrorAbsorbed << " lm, direct pass " << 100 * b.directError() << " %, secondary "
                    << 100 * b.secondaryError() << " %");
    CHECK(b.mirrorAbsorbed > 0.05 * b.emitted);
    CHECK(std::abs(b.directError()) < 1e-3);
    CHECK(std::abs(b.relativeError()) < 1e-3);
}

TEST_CASE("the same room in millimetres and kilometres gives the same illuminance within 0.1 %", "[stability]") {
    auto values = [](double s) {
        // Intensity × s² keeps the illuminance unchanged.
        auto run =
            app::runPipeline(test::writeTempScene(fmt::format("scaled_{}", s), boxRoom(s, 0.5, 100 * s * s)), quiet());
        REQUIRE(allFinite(run));
        std::vector<double> out;
        for (const auto& r : run.sensors) out.push_back(luminance(r.value.direct + r.value.indirect));
        return out;
    };
    auto metres = values(1), millimetres = values(1e-3), kilometres = values(1e3);
    for (size_t k = 0; k < metres.size(); ++k) {
        INFO("sensor " << k << ": m " << metres[k] << ", mm " << millimetres[k] << ", km " << kilometres[k]);
        CHECK(millimetres[k] == Approx(metres[k]).epsilon(1e-3));
        CHECK(kilometres[k] == Approx(metres[k]).epsilon(1e-3));
    }
}

TEST_CASE("a point light 1 mm from a wall: exact direct light at its foot, finite everywhere", "[stability]") {
    std::string json = boxRoom(1, 0.5, 10, "", "");
    // Move the light to 1 mm in front of the wall x = 0 and put a sensor at its foot.
    json.replace(json.find("[1.3, 2.1, 1.7]"), std::string("[1.3, 2.1, 1.7]").size(), "[0.001, 1.4, 2.6]");
    auto run = app::runPipeline(test::writeTempScene("light_at_wall", json), quiet());
    REQUIRE(allFinite(run));
    const auto& wall = run.sensors[1];                                                  // at (0, 1.4, 2.6), facing +x
    CHECK(luminance(wall.value.direct) == Approx(10 / (0.001 * 0.001)).epsilon(1e-6));  // E = I / d²
    // The patch under the light gets almost half the flux, in a peak 1 mm wide: the
    // direct pass takes its mean from the solid angle, so nothing is lost.
    CHECK(std::abs(notAccounted(run)) < 1e-3);
}

TEST_CASE("touching, overlapping and broken geometry: no NaN, no crash, degenerate triangles dropped", "[stability]") {
    // A mesh with a zero-area and a duplicate triangle and a T-junction, a quad coplanar
    // with the floor and overlapping it, a box touching two walls, sensors at grazing angles.
    std::string obj = "/tmp/rayrad_test_broken.obj";
    std::ofstream(obj) << "v 1 0.5 1\nv 2 0.5 1\nv 1 0.5 2\nv 2 0.5 2\nv 1.5 0.5 1\nv 3 0.5 1\n"
                          "f 1 3 2\nf 2 3 4\nf 1 3 2\nf 1 5 6\n";  // duplicate; zero-area (collinear)
    std::string extra = fmt::format(R"(, {{"type": "mesh", "material": "m", "file": "{}"}},
        {{"type": "quad", "material": "m", "vertices": [[0.5, 0, 0.5], [0.5, 0, 1.5], [1.5, 0, 1.5], [1.5, 0, 0.5]]}},
        {{"type": "box", "material": "m", "min": [3, 0, 4], "max": [4, 1, 5]}})",
                                    obj);
    std::string json = boxRoom(1, 0.5, 100, extra);
    json.replace(json.find("\"sensors\": ["), std::string("\"sensors\": [").size(),
                 R"("sensors": [{"name": "grazing", "position": [2, 0, 2], "normal": [0.9999, 0.0141, 0]},
                                {"name": "edge", "position": [0, 0, 2], "normal": [0.7071, 0.7071, 0]},)");
    auto run = app::runPipeline(test::writeTempScene("broken_geometry", json), quiet());
    CHECK(run.scene.warnings.degeneratePolygons == 2);
    REQUIRE(allFinite(run));
    for (const auto& s : run.sensors) CHECK(luminance(s.value.direct + s.value.indirect) > 0);
}

TEST_CASE("10 000 point lights, and lights 10^6 apart in one scene", "[stability]") {
    SECTION("10 000 lights") {
        std::string lights;
        for (int k = 0; k < 10000; ++k)
            lights += fmt::format(R"(, {{"type": "point", "position": [{}, {}, {}], "intensity_cd": 0.01}})",
                                  0.2 + 3.6 * ((k * 37) % 100) / 100.0, 1.0 + 1.0 * (k % 7) / 7.0,
                                  0.2 + 4.6 * ((k * 13) % 97) / 97.0);
        auto run = app::runPipeline(test::writeTempScene("many_lights", boxRoom(1, 0.5, 1, "", lights)), quiet());
        REQUIRE(run.scene.lights.size() == 10001);
        REQUIRE(allFinite(run));
        CHECK(std::abs(notAccounted(run)) < 1e-3);
    }
    SECTION("1e6 and 1 cd") {
        auto json = boxRoom(1, 0.5, 1e6, "", R"(, {"type": "point", "position": [3, 1, 4], "intensity_cd": 1})");
        auto run = app::runPipeline(test::writeTempScene("wide_range", json), quiet());
        REQUIRE(allFinite(run));
        CHECK(std::abs(notAccounted(run)) < 1e-3);
    }
}
