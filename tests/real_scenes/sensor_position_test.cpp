// Issue 11, item 4 (part): the gather never counts the sensor's own surface. At some exact
// positions on a plain wall it read +85…+95 % (the wall's own exitance): a point a hair in
// front of its own patch saw it fill the hemisphere. The cube is symmetric, so a grid on
// one wall must read the same at every point and its mirror images.
#include <app/pipeline.h>

#include "pipeline_test_util.h"
#include "test_support.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

using namespace rayrad;

TEST_CASE("cube, 19 200 triangles: a 32 x 32 sensor grid on a wall is symmetric to 0.05 % (no sensor counts its own wall)",
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
