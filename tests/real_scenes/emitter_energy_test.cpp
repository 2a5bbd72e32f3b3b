// "energy is never created": every emitter shape, close to a surface or not,
// facing it or away from it, delivers exactly its flux into a closed box.
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

/// A black closed box 4 × 3 × 4 m with a regular n-gon emitter (radius 0.4 m, 1 000 lm)
/// `gap` metres below the ceiling, facing down (`faceUp` false) or toward the ceiling.
/// Black walls leave only the direct pass, whose account must close by itself.
std::string ngonRoom(int sides, double gap, bool faceUp) {
    std::string vertices;
    for (int k = 0; k < sides; ++k) {
        int i = faceUp ? sides - 1 - k : k;
        double a = 2 * kPi * i / sides + 0.3;  // not aligned with the mesh
        vertices += fmt::format("{}[{:.17g}, {:.17g}, {:.17g}]", k ? ", " : "", 2 + 0.4 * std::cos(a), 3 - gap,
                                2 + 0.4 * std::sin(a));
    }
    return fmt::format(
        R"({{"materials": {{"black": {{"reflectance": 0}}, "lamp": {{"type": "emissive", "flux_lm": 1000}}}},
        "objects": [{{"type": "box", "material": "black", "min": [0, 0, 0], "max": [4, 3, 4], "facing": "inward"}},
                    {{"type": "polygon", "material": "lamp", "vertices": [{}]}}]}})",
        vertices);
}

}  // namespace

TEST_CASE(
    "emitters of 3, 4, 6 and 24 sides, 1 cm to 1 m from a ceiling, facing it or not: direct pass "
    "delivers the emitted flux within 0.1 %",
    "[real_scenes]") {
    int sides = GENERATE(3, 4, 6, 24);
    double gap = GENERATE(0.01, 0.2, 1.0);
    bool faceUp = GENERATE(false, true);
    auto run = app::runPipeline(
        test::writeTempScene(fmt::format("ngon_{}_{}_{}", sides, gap, faceUp), ngonRoom(sides, gap, faceUp)), quiet());
    auto b = app::energyBalanceOf(run);
    INFO(sides << " sides, " << gap << " m below the ceiling, facing " << (faceUp ? "up" : "down") << ": emitted "
               << b.emitted << " lm, received " << b.directReceived << " lm");
    CHECK(b.emitted == Approx(1000).epsilon(1e-9));
    CHECK(std::abs(b.directError()) < 1e-3);
}
