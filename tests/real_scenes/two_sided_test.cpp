// item 5: two-sided diffuse surfaces ("two_sided": true, optional
// "back_reflectance"), in the radiosity and in the ray tracer.
#include <app/pipeline.h>
#include <radiosity/shooting/shooting_solver.h>
#include <radiosity/solution/energy_balance.h>

#include "pipeline_test_util.h"
#include "test_support.h"

#include <cmath>
#include <string>

using namespace rayrad;

namespace {

/// A closed room with a free-standing panel (a blind) in the middle, lit on its back
/// side; a camera looks at that side.
std::string roomWithBlind(const std::string& blind) {
    return R"({"materials": {"wall": {"reflectance": 0.5}, "blind": )" + blind + R"(},
        "objects": [{"type": "box", "material": "wall", "min": [0, 0, 0], "max": [4, 3, 4], "facing": "inward"},
                    {"type": "quad", "material": "blind", "vertices": [[1.5, 0.5, 2], [2.5, 0.5, 2], [2.5, 2.5, 2], [1.5, 2.5, 2]]}],
        "lights": [{"type": "point", "position": [2, 1.5, 0.5], "intensity_cd": 100}],
        "sensors": [{"name": "lit side", "position": [2, 1.5, 2], "normal": [0, 0, -1]}],
        "camera": {"position": [2, 1.5, 0.3], "look_at": [2, 1.5, 2], "vfov_deg": 60, "resolution": [32, 24]},
        "render": {"spp": 1}})";
}

app::PipelineOptions withImage() {
    auto o = test::quiet();
    o.wantImage = true;
    return o;
}

}  // namespace

TEST_CASE("two-sided diffuse: a blind lit from behind reflects on both sides, the account closes, the back renders",
          "[real_scenes]") {
    auto oneSided = app::runPipeline(test::writeTempScene("blind_one_sided", roomWithBlind(R"({"reflectance": 0.8})")),
                                     withImage());
    auto twoSided = app::runPipeline(
        test::writeTempScene("blind_two_sided",
                             roomWithBlind(R"({"reflectance": 0.8, "two_sided": true, "back_reflectance": 0.2})")),
        withImage());
    auto lost = app::energyBalanceOf(oneSided);
    auto closed = app::energyBalanceOf(twoSided);
    INFO("one-sided: " << 100 * lost.backShare() << " % on backs, not accounted " << 100 * lost.relativeError()
                       << " %; two-sided: " << 100 * closed.backShare() << " % on backs, not accounted "
                       << 100 * closed.relativeError() << " %");
    // One-sided, the light on the blind's back is absorbed there (and booked).
    CHECK(lost.backShare() > 0.01);
    CHECK(std::abs(lost.relativeError()) < 1e-3);
    CHECK(closed.backShare() < 1e-3);
    CHECK(std::abs(closed.relativeError()) < 1e-3);

    // The lit side is the back (reflectance 0.2): the image's centre shows
    // L = ρ_back (E_direct + E_indirect) / π; the one-sided back is black.
    const auto& s = twoSided.sensors[0];
    REQUIRE(s.value.indirectVertex);
    const double expected = 0.2 * luminance(s.value.direct + *s.value.indirectVertex) / kPi;
    const double centre = luminance(twoSided.image->at(16, 12));
    INFO("centre pixel " << centre << " cd/m², expected " << expected);
    CHECK(centre == Approx(expected).epsilon(0.05));
    CHECK(luminance(oneSided.image->at(16, 12)) == 0.0);
    bool backMaterial = false;
    for (const auto& m : twoSided.scene.materials) backMaterial |= m.name == "blind (back)" && m.reflectance.r == 0.2;
    CHECK(backMaterial);
}

TEST_CASE("back-to-back quads (a zero-thickness wall) render without black patches from either side", "[real_scenes]") {
    // The two quads coincide: the nearest hit is a back face about half the time. The
    // ray tracer takes the coincident front face instead of a black back.
    std::string json = R"({"materials": {"wall": {"reflectance": 0.6}},
        "objects": [{"type": "box", "material": "wall", "min": [0, 0, 0], "max": [8, 3, 4], "facing": "inward"},
                    {"type": "quad", "material": "wall", "vertices": [[4,0,0],[4,0,4],[4,3,4],[4,3,0]]},
                    {"type": "quad", "material": "wall", "vertices": [[4,0,0],[4,3,0],[4,3,4],[4,0,4]]}],
        "lights": [{"type": "point", "position": [2, 2.5, 2], "intensity_cd": 1000},
                   {"type": "point", "position": [6, 2.5, 2], "intensity_cd": 1000}],
        "camera": {"position": [0.3, 1.5, 2], "look_at": [4, 1.5, 2], "vfov_deg": 40, "resolution": [32, 24]},
        "render": {"spp": 1}})";
    for (double side : {0.3, 7.7}) {
        std::string scene = json;
        if (side > 4) scene.replace(scene.find("[0.3, 1.5, 2]"), std::string("[0.3, 1.5, 2]").size(), "[7.7, 1.5, 2]");
        auto run = app::runPipeline(test::writeTempScene("back_to_back", scene), withImage());
        int black = 0;
        for (const auto& px : run.image->pixels) black += luminance(px) <= 0;
        INFO("camera at x = " << side << ": " << black << " black pixels of " << run.image->pixels.size());
        CHECK(black == 0);
    }
}
