// item 4 (part): the gather never counts the sensor's own surface. At some exact
// positions on a plain wall it read +85…+95 % (the wall's own exitance): a point a hair in
// front of its own patch saw it fill the hemisphere. The cube is symmetric, so a grid on
// one wall must read the same at every point and its mirror images.
#include <app/pipeline.h>
#include <radiosity/gather/gather.h>

#include "pipeline_test_util.h"
#include "test_support.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

using namespace rayrad;

TEST_CASE(
    "cube, 19 200 triangles: a 32 x 32 sensor grid on a wall is symmetric to 0.05 % (no sensor counts its own wall)",
    "[real_scenes]") {
    std::string json = R"({"materials": {"wall": {"reflectance": 0.6666666666666666}},
        "objects": [{"type": "box", "material": "wall", "min": [0, 0, 0], "max": [10, 10, 10], "facing": "inward"}],
        "lights": [{"type": "point", "position": [5, 5, 5], "intensity_cd": 50000}],
        "sensor_grids": [{"name": "g", "origin": [0.15625, 0.15625, 10], "u": [9.6875, 0, 0], "v": [0, 9.6875, 0],
                          "counts": [32, 32], "normal": [0, 0, -1]}],
        "radiosity": {"max_edge": 0.25}})";
    auto run = app::runPipeline(test::writeTempScene("cube_grid", json), test::quiet());
    REQUIRE(run.sensors.size() == 1024);
    // Grid index from the position: cell centres at 0.15625 + (i + 0.5) · 9.6875 / 32.
    std::map<std::pair<int, int>, double> value;
    for (const auto& s : run.sensors) {
        int i = static_cast<int>(std::lround((s.sensor.position.x - 0.15625) / (9.6875 / 32) - 0.5));
        int j = static_cast<int>(std::lround((s.sensor.position.y - 0.15625) / (9.6875 / 32) - 0.5));
        value[{i, j}] = luminance(s.value.indirect);
    }
    REQUIRE(value.size() == 1024);
    double worst = 0;
    std::pair<int, int> at{0, 0};
    for (const auto& [ij, v] : value) {
        auto [i, j] = ij;
        std::vector<double> images = {value[{31 - i, j}], value[{i, 31 - j}], value[{31 - i, 31 - j}], value[{j, i}],
                                      value[{31 - j, i}], value[{j, 31 - i}], value[{31 - j, 31 - i}], v};
        std::sort(images.begin(), images.end());
        double median = 0.5 * (images[3] + images[4]);
        double deviation = std::abs(v / median - 1);
        if (deviation > worst) worst = deviation, at = ij;
    }
    INFO("largest deviation from the symmetric images " << 100 * worst << " % at (" << at.first << ", " << at.second
                                                        << ")");
    CHECK(worst < 5e-4);
}

TEST_CASE("sensors are located through Embree's spatial index exactly as by a scan of every patch", "[real_scenes]") {
    // A floor with a box standing on it off the floor's grid (contact lines cut the floor
    // along the box's foot, with vertex copies on each side) and a thin partition: the
    // places where several patches and surfaces meet at a point.
    std::string json = R"({"materials": {"m": {"reflectance": 0.5}, "wall": {"reflectance": 0.5, "two_sided": true}},
        "objects": [
          {"type": "quad", "material": "m", "vertices": [[0,0,0],[0,0,4],[4,0,4],[4,0,0]]},
          {"type": "box", "material": "m", "min": [1.3, 0, 1.45], "max": [2.3, 1, 2.45]},
          {"type": "quad", "material": "wall", "vertices": [[3,0,0],[3,2,0],[3,2,4],[3,0,4]]}],
        "lights": [{"type": "point", "position": [2, 3, 3], "intensity_cd": 100}],
        "radiosity": {"max_edge": 0.5}})";
    auto run = app::runPipeline(test::writeTempScene("locate_index", json), test::quiet());
    const auto& mesh = run.mesh;
    const double tolerance = 1e-6 * run.scene.diagonal();
    size_t points = 0, located = 0, boundaries = 0;
    auto check = [&](const Vec3& x, const Vec3& n) {
        ++points;
        const auto scan = radiosity::locateOnMesh(mesh, x, n, tolerance);
        const auto indexed = radiosity::locateOnMesh(mesh, x, n, tolerance, run.embree.get());
        REQUIRE(scan.has_value() == indexed.has_value());
        if (!scan) return;
        ++located;
        CHECK(scan->patch == indexed->patch);
        CHECK(scan->u == indexed->u);
        CHECK(scan->v == indexed->v);
        const bool rim = radiosity::onSurfaceBoundary(mesh, *scan, 10 * tolerance);
        CHECK(rim == radiosity::onSurfaceBoundary(mesh, *scan, 10 * tolerance, run.embree.get()));
        boundaries += rim;
    };
    for (const auto& p : mesh.patches) {
        const Vec3 a = mesh.corner(p, 0), b = mesh.corner(p, 1), c = mesh.corner(p, 2);
        for (const Vec3& x :
             {a, 0.5 * (a + b), p.centroid, 0.2 * a + 0.3 * b + 0.5 * c, a + 0.3 * tolerance * p.normal})
            check(x, p.normal);
        check(p.centroid + 1e-3 * p.normal, p.normal);  // off the surface: on none
    }
    INFO(points << " points, " << located << " on a surface, " << boundaries << " on a rim");
    CHECK(located > points / 2);
    CHECK(boundaries > 0);
}
