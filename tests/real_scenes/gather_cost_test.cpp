// item 4 (part): a sensor's cost is bounded by what its re-gathers can still
// change. Inside a finely tessellated sphere every facet near a point faces it (the
// surface is concave), so a point 1 cm from the wall has hundreds of near patches, each
// of whose corners would be re-gathered `gather_levels` deep, with hundreds of near
// patches of their own: the living room's sensors beside dense furniture took minutes.
// The indirect light inside a closed diffuse sphere is uniform, ρ/(1−ρ) Φ/A, so the
// answer is known at any point and in any direction.
#include <app/pipeline.h>

#include "pipeline_test_util.h"
#include "test_support.h"

#include <fmt/format.h>

#include <cmath>

using namespace rayrad;

namespace {

/// The closed sphere (ρ = 0.5, 100 cd at the centre: E_ind = ρ/(1−ρ) · 4π·100 / 4π =
/// 100 lx) with sensors 1 cm inside its wall, facing the wall and along it.
std::string sphereWithSensorsNearTheWall(int subdivisions) {
    return fmt::format(R"({{"materials": {{"m": {{"reflectance": 0.5}}}},
        "objects": [{{"type": "sphere", "material": "m", "radius": 1, "subdivisions": {}, "facing": "inward"}}],
        "lights": [{{"type": "point", "position": [0, 0, 0], "intensity_cd": 100}}],
        "sensors": [{{"name": "facing", "position": [0.1, 0.05, 0.985], "normal": [0, 0, 1]}},
                    {{"name": "along", "position": [0.05, 0.985, 0.1], "normal": [1, 0, 0]}}]}})",
                       subdivisions);
}

}  // namespace

TEST_CASE(
    "sensors 1 cm inside a finely tessellated sphere: within 1 % of the uniform 100 lx, in a bounded "
    "number of gathers",
    "[real_scenes]") {
    const std::string path = test::writeTempScene("gather_cost_sphere", sphereWithSensorsNearTheWall(24));
    const double expected = 100.0;  // lx, ρ/(1−ρ) Φ/A
    // Eight levels, so the bound has a deep recursion to cut.
    auto bounded = app::runPipeline(path, test::quiet({{"radiosity.gather_levels", "8"}}));
    auto full = app::runPipeline(
        path, test::quiet({{"radiosity.gather_levels", "8"}, {"radiosity.gather_min_weight", "0"}}));
    REQUIRE(bounded.sensors.size() == 2);
    for (size_t i = 0; i < 2; ++i) {
        const double b = luminance(bounded.sensors[i].value.indirect), f = luminance(full.sensors[i].value.indirect);
        INFO(bounded.sensors[i].sensor.name << ": bounded " << b << " lx, full depth " << f << " lx");
        CHECK(std::abs(b / expected - 1) < 0.01);
        CHECK(std::abs(b / f - 1) < 0.002);  // the bound moves the value by less than 0.2 %
    }
    INFO("gathers: bounded " << bounded.lighting.sensorGathers << ", full depth " << full.lighting.sensorGathers);
    CHECK(bounded.lighting.sensorGathers * 10 < full.lighting.sensorGathers);
}
