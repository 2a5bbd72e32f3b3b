// Grids on surfaces of the scene: a material's faces, split into surfaces by
// plane and contact, each with its own grid; boxes and an imported mesh.
#include <app/pipeline.h>
#include <core/input_error.h>
#include <scene/scene_parser.h>

#include "pipeline_test_util.h"
#include "test_support.h"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <fstream>
#include <map>

using namespace rayrad;

namespace {

/// A room with two 1.6 × 0.8 m desks (tops at 0.75 m) and `extra` objects; `grids` spliced in.
std::string room(const std::string& grids, const std::string& extra = "") {
    return R"({"materials": {"w": {"reflectance": 0.5}, "desk": {"reflectance": 0.4}, "table": {"reflectance": 0.3}},
        "objects": [{"type": "box", "min": [0, 0, 0], "max": [5, 2.8, 4], "facing": "inward", "material": "w"},
                    {"type": "box", "min": [0.5, 0, 0.5], "max": [2.1, 0.75, 1.3], "material": "desk"},
                    {"type": "box", "min": [3, 0, 2], "max": [4.6, 0.75, 2.8], "material": "desk"})" +
           extra + R"(],
        "lights": [{"type": "point", "position": [2.5, 2.5, 2], "intensity_cd": 500}],
        "surface_grids": [)" +
           grids + R"(], "radiosity": {"max_edge": 0.5}})";
}

scene::Scene build(const std::string& json) { return scene::buildScene(scene::parseScene(json, "/tmp/rayrad_test_surface.json")); }

std::string errorOf(const std::string& json) {
    try {
        build(json);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("a surface grid covers each desk top: one grid per surface, points on the faces, facing up", "[scene][grids]") {
    const auto s = build(room(R"({"name": "top", "material": "desk", "facing": [0, 1, 0], "spacing": 0.2, "offset": 0.01})"));
    std::map<std::string, int> perGrid;
    for (const auto& p : s.sensors) {
        ++perGrid[p.grid];
        CHECK(p.position.y == Approx(0.76));
        CHECK(p.normal.y == Approx(1.0));
    }
    CHECK(perGrid == std::map<std::string, int>{{"top#1", 32}, {"top#2", 32}});  // 8 × 4 cells of 0.2 m each
    CHECK(s.sensors[0].name == "top#1[0,0]");
    CHECK(s.sensors[0].position.x == Approx(0.6));
    CHECK(s.sensors[0].position.z == Approx(0.6));
    // Without `facing`, every face of the desks: tops, sides, bottoms, each its own surface.
    const auto all = build(room(R"({"name": "all", "material": "desk", "spacing": 0.2})"));
    std::map<std::string, int> faces;
    for (const auto& p : all.sensors) ++faces[p.grid];
    CHECK(faces.size() == 12);
    // EN 12464-1 spacing by default: d = 1.6 m, p = 0.2 · 5^log10(1.6) = 0.278 m: 6 × 3.
    const auto standard = build(room(R"({"name": "en", "material": "desk", "facing": [0, 1, 0]})"));
    CHECK(standard.sensors.size() == 2 * 6 * 3);
}

TEST_CASE("a surface grid on an imported mesh: triangles of one plane that touch make one surface", "[scene][grids]") {
    // A table top of two triangles (1.2 × 0.6 m at 0.7 m) and a leg's end (5 cm square,
    // facing up, below the top): the leg is smaller than min_area and gets no grid.
    const std::string obj = "/tmp/rayrad_test_table.obj";
    std::ofstream(obj) << "v 1 0.7 1\nv 2.2 0.7 1\nv 2.2 0.7 1.6\nv 1 0.7 1.6\n"
                          "v 1.1 0.1 1.1\nv 1.15 0.1 1.1\nv 1.15 0.1 1.15\nv 1.1 0.1 1.15\n"
                          "f 1 4 3\nf 1 3 2\nf 5 8 7\nf 5 7 6\n";
    const auto s = build(room(R"({"name": "table", "material": "table", "facing": [0, 1, 0], "spacing": 0.1})",
                              R"(, {"type": "mesh", "file": "rayrad_test_table.obj", "material": "table"})"));
    std::map<std::string, int> perGrid;
    for (const auto& p : s.sensors) ++perGrid[p.grid];
    INFO(fmt::format("{} grids, {} points", perGrid.size(), s.sensors.size()));
    CHECK(perGrid == std::map<std::string, int>{{"table", 72}});  // 12 × 6
}

TEST_CASE("surface grids: mistakes are named", "[scene][grids]") {
    CHECK_THAT(errorOf(room(R"({"name": "x", "material": "desks"})")),
               Catch::Contains("/surface_grids/0/material: no material \"desks\" in the scene (it has: desk, table, w)"));
    CHECK_THAT(errorOf(room(R"({"name": "x", "material": "desk", "facing": [1, 1, 0]})")),
               Catch::Contains("/surface_grids/0/facing: no face of material \"desk\" faces that way"));
    CHECK_THAT(errorOf(room(R"({"name": "x", "material": "desk", "spacing": 0.0001})")),
               Catch::Contains("/surface_grids/0/spacing: a spacing of 0.0001 m puts more than 1000000 points"));
    CHECK_THAT(errorOf(room(R"({"name": "x", "material": "desk", "min_area": 5})")),
               Catch::Contains("/surface_grids/0/min_area: no surface of \"desk\" has 5 m² or more"));
    CHECK_THAT(errorOf(room(R"({"name": "x", "material": "desk", "facing": [0, 1, 0]}, {"name": "x", "material": "desk", "facing": [0, 1, 0]})")),
               Catch::Contains("/surface_grids/1/name: sensor name \"x#1[0,0]\" is used twice"));
}

TEST_CASE("a surface grid point reads what a sensor at the same place reads", "[scene][grids]") {
    const std::string json = room(R"({"name": "top", "material": "desk", "facing": [0, 1, 0], "spacing": 0.4})");
    const std::string withSensor = json.substr(0, json.rfind('}')) +
                                   R"(, "sensors": [{"name": "same", "position": [0.7, 0.75, 0.7], "normal": [0, 1, 0]}]})";
    auto run = app::runPipeline(test::writeTempScene("surface_grid_sensor", withSensor), test::quiet());
    const auto& sensors = run.sensors;
    const auto& plain = sensors[0];
    REQUIRE(plain.sensor.name == "same");
    const auto grid = std::find_if(sensors.begin(), sensors.end(), [](const auto& r) { return r.sensor.name == "top#1[0,0]"; });
    REQUIRE(grid != sensors.end());
    CHECK(grid->sensor.position.x == Approx(0.7));
    CHECK(luminance(grid->value.direct) == Approx(luminance(plain.value.direct)).epsilon(1e-9));
    // The same place to rounding: the gather's adaptive choices may differ in the last digits.
    CHECK(luminance(grid->value.indirect) == Approx(luminance(plain.value.indirect)).epsilon(1e-4));
    CHECK(luminance(grid->value.direct) > 0);
}
