// "energy is never created … through any mirror chain": the living room's wall
// mirror (a mirror quad framed by four bevel strips tilted 5.7°, hanging 2 cm in front of
// the wall) in a closed box. The account must close whatever lights it and whether light
// can enter the gap behind it; a mirror wound backwards books what falls on its back.
#include <app/pipeline.h>
#include <radiosity/shooting/shooting_solver.h>
#include <radiosity/solution/energy_balance.h>

#include "pipeline_test_util.h"
#include "test_support.h"

#include <fmt/format.h>

#include <cmath>
#include <string>

using namespace rayrad;
using test::quiet;

namespace {

/// The box 6 × `height` × 3 m (z from −3 to 0: the mirror hangs on the wall z = 0), walls
/// ρ = 0.5, the five mirror quads (Ks 0.9) `gap` metres in front of the wall at their
/// rim, and a 24-gon lamp (1 000 cd/m², radius 0.5 m) 3 cm below the ceiling or a
/// 100 cd point light.
/// `extra`: more members of the scene object (after a comma), `moreObjects`: more objects.
std::string mirrorRoom(double height, bool areaLight, double gap, const std::string& moreObjects = "",
                       const std::string& extra = "") {
    const double rim = -gap, inner = -gap - 0.004025;  // the bevel strips fall 4 mm
    const std::string quads[5] = {
        fmt::format("[[2.242764, 0.94999, {0}], [1.513164, 0.94999, {0}], [1.553164, 0.98999, {1}], "
                    "[2.202764, 0.98999, {1}]]",
                    rim, inner),
        fmt::format("[[2.242764, 2.277397, {0}], [2.242764, 0.94999, {0}], [2.202764, 0.98999, {1}], "
                    "[2.202764, 2.237397, {1}]]",
                    rim, inner),
        fmt::format("[[1.513164, 2.277397, {0}], [2.242764, 2.277397, {0}], [2.202764, 2.237397, {1}], "
                    "[1.553164, 2.237397, {1}]]",
                    rim, inner),
        fmt::format("[[1.513164, 0.94999, {0}], [1.513164, 2.277397, {0}], [1.553164, 2.237397, {1}], "
                    "[1.553164, 0.98999, {1}]]",
                    rim, inner),
        fmt::format("[[1.553164, 2.237397, {1}], [2.202764, 2.237397, {1}], [2.202764, 0.98999, {1}], "
                    "[1.553164, 0.98999, {1}]]",
                    rim, inner)};
    std::string objects = fmt::format(
        R"({{"type": "box", "material": "wall", "min": [0, 0, -3], "max": [6, {}, 0], "facing": "inward"}})", height);
    for (const auto& q : quads)
        objects += fmt::format(R"(, {{"type": "quad", "material": "mirror", "vertices": {}}})", q);
    objects += moreObjects;
    std::string lights = "[]";
    if (areaLight) {
        std::string vertices;
        for (int k = 0; k < 24; ++k) {
            const double a = 2 * kPi * k / 24;  // counter-clockwise seen from below: faces down
            vertices += fmt::format("{}[{:.17g}, {}, {:.17g}]", k ? ", " : "", 2.663 + 0.5 * std::cos(a), height - 0.03,
                                    -1.645 + 0.5 * std::sin(a));
        }
        objects += fmt::format(R"(, {{"type": "polygon", "material": "lamp", "vertices": [{}]}})", vertices);
    } else {
        lights =
            fmt::format(R"([{{"type": "point", "position": [2.66, {}, -1.645], "intensity_cd": 100}}])", height - 0.1);
    }
    return fmt::format(R"({{"materials": {{"wall": {{"reflectance": 0.5}},
        "lamp": {{"type": "emissive", "luminance_cd_m2": 1000}},
        "mirror": {{"type": "mirror", "specular_reflectance": 0.9}}}},
        "objects": [{}], "lights": {}{}}})",
                       objects, lights, extra);
}

}  // namespace

TEST_CASE(
    "a wall mirror with tilted bevel strips in a closed box: the account closes within 0.1 % for an area "
    "or a point light, with or without a gap behind it",
    "[real_scenes]") {
    const bool areaLight = GENERATE(true, false);
    const double gap = GENERATE(0.019778, 0.0);
    const double height = GENERATE(2.9, 3.5);
    auto run = app::runPipeline(test::writeTempScene(fmt::format("wall_mirror_{}_{}_{}", areaLight, gap, height),
                                                     mirrorRoom(height, areaLight, gap)),
                                quiet());
    auto b = app::energyBalanceOf(run);
    INFO((areaLight ? "24-gon lamp" : "point light")
         << ", gap " << gap << " m, ceiling " << height << " m: direct " << 100 * b.directError() << " %, secondary "
         << 100 * b.secondaryError() << " %, mirrors absorbed " << b.mirrorAbsorbed << " lm");
    CHECK(run.lighting.mirrorImages() == 5);
    CHECK(b.mirrorAbsorbed > 0);
    CHECK(std::abs(b.directError()) < 1e-3);
    CHECK(std::abs(b.relativeError()) < 1e-3);
}

TEST_CASE("light on the back of a mirror wound backwards is booked as absorbed there, with a warning",
          "[real_scenes]") {
    // The mirror at x = 0.5 faces the wall behind it (−x): the lamp lights its back.
    auto run = app::runPipeline(test::writeTempScene("mirror_backwards", R"({
        "materials": {"wall": {"reflectance": 0.5}, "lamp": {"type": "emissive", "flux_lm": 1000},
                      "mirror": {"type": "mirror", "specular_reflectance": 0.9}},
        "objects": [{"type": "box", "material": "wall", "min": [0, 0, 0], "max": [4, 3, 4], "facing": "inward"},
                    {"type": "quad", "material": "mirror", "vertices": [[0.5, 1, 1], [0.5, 1, 3], [0.5, 2.5, 3], [0.5, 2.5, 1]]},
                    {"type": "polygon", "material": "lamp", "vertices": [[1.5, 2.98, 1.5], [2.5, 2.98, 1.5], [2.0, 2.98, 2.5]]}]})"),
                                quiet());
    auto b = app::energyBalanceOf(run);
    INFO("on backs " << b.backAbsorbed << " lm of " << b.emitted << "; not accounted " << 100 * b.relativeError()
                     << " %");
    CHECK(b.backAbsorbed > 0.02 * b.emitted);
    CHECK(std::abs(b.relativeError()) < 1e-3);
    bool warned = false;
    for (const auto& w : run.warnings) warned |= w.find("backs of one-sided surfaces") != std::string::npos;
    CHECK(warned);
}

TEST_CASE("mirror chains that can carry almost no light are cut by their etendue share, and the sensors hardly move",
          "[real_scenes]") {
    // The wall mirror with its bevel strips facing a 2 × 1.5 m mirror on the opposite
    // wall: chains between the big mirrors carry light, those through the 4 cm strips
    // and back almost none (rays at grazing angles through a few square centimetres).
    const std::string facing =
        R"(, {"type": "quad", "material": "mirror", "vertices": [[1, 0.8, -2.99], [3, 0.8, -2.99], [3, 2.3, -2.99], [1, 2.3, -2.99]]})";
    const std::string sensors = R"(, "sensors": [
        {"name": "floor", "position": [2, 0, -1.5], "normal": [0, 1, 0]},
        {"name": "side wall", "position": [0, 1.5, -1.5], "normal": [1, 0, 0]},
        {"name": "ceiling", "position": [4, 2.9, -1], "normal": [0, -1, 0]}],
        "radiosity": {"max_edge": 0.5, "mirror_depth": 3, "mirror_min_share": )";
    auto runWith = [&](double share) {
        return app::runPipeline(
            test::writeTempScene(fmt::format("mirror_share_{}", share),
                                 mirrorRoom(2.9, false, 0.019778, facing, sensors + fmt::format("{}}}", share))),
            quiet());
    };
    auto all = runWith(0), cut = runWith(1e-5);
    INFO("images: " << all.lighting.mirrorImages() << " all, " << cut.lighting.mirrorImages() << " with the cut");
    CHECK(cut.lighting.mirrorImages() >=
          6);  // the five single mirrors, the facing one and its chains with the big mirror
    CHECK(cut.lighting.mirrorImages() * 3 < all.lighting.mirrorImages() * 2);  // 46 -> 22 when written
    REQUIRE(all.sensors.size() == cut.sensors.size());
    for (size_t k = 0; k < all.sensors.size(); ++k) {
        const double a = luminance(all.sensors[k].value.direct + all.sensors[k].value.indirect);
        const double c = luminance(cut.sensors[k].value.direct + cut.sensors[k].value.indirect);
        INFO(all.sensors[k].sensor.name << ": " << a << " lx with every chain, " << c << " lx with the cut");
        CHECK(c == Approx(a).epsilon(1e-4));
    }
}
