// The sensor gather beside an input mesh's slivers (a molding's strips): not refined with
// gathered midpoints, so a point in a room's corner does not cost a minute (the living
// room: 57.6 → 28.2 CPU-s for one such point).
#include <radiosity/gather/gather.h>
#include <radiosity/solution/solution.h>
#include "solved_scene.h"

#include "test_support.h"

#include <fmt/format.h>

using namespace rayrad;
using namespace rayrad::radiosity;

TEST_CASE("sensor gather: a chamfer molding of 4 mm strips beside the point is not refined strip by strip",
          "[solver]") {
    // A floor and a wall meeting at z = 0, and between them a 45° chamfer 0.12 m across made
    // of 40 strips 2 m long and 4.2 mm wide (as an imported molding is): each strip is
    // "near" a floor point a few millimetres in front of the chamfer's foot by its length,
    // though a sliver; the gather refined each toward the point with gathered midpoints.
    // A minimum weight of 0.01 re-gathers near patches down to 1 % of the near field's share,
    // so the rule, not the weight, is what leaves the strips alone here.
    std::string objects = R"(
        {"type": "quad", "material": "m", "vertices": [[0,0,0],[0,0,2],[2,0,2],[2,0,0]]},
        {"type": "quad", "material": "m", "vertices": [[0,0,0],[2,0,0],[2,2,0],[0,2,0]]},
        {"type": "quad", "material": "m", "vertices": [[0,2,0],[2,2,0],[2,2,2],[0,2,2]]})";
    const int strips = 40;
    for (int k = 0; k < strips; ++k) {
        const double a = 0.12 * k / strips, b = 0.12 * (k + 1) / strips;  // along the chamfer, from the floor
        // The chamfer runs from (y 0, z 0.12) on the floor to (y 0.12, z 0) on the wall.
        objects += fmt::format(
            R"(, {{"type": "quad", "material": "m", "vertices": [[0,{0},{1}],[2,{0},{1}],[2,{2},{3}],[0,{2},{3}]]}})",
            a, 0.12 - a, b, 0.12 - b);
    }
    const std::string json = R"({"materials": {"m": {"reflectance": 0.6}},
        "objects": [)" + objects +
                             R"(],
        "lights": [{"type": "point", "position": [1, 0.4, 0.5], "intensity_cd": 100}],
        "radiosity": {"max_edge": 0.25, "gather_min_weight": 0.01}})";
    auto run = test::solve(test::writeTempScene("chamfer_strips", json));
    const GatherOptions options = GatherOptions::forSensors(run.scene, run.mesh);
    REQUIRE(options.minRefineWidth == Approx(0.05 * 0.25));
    GatherOptions everyStrip = options;
    everyStrip.minRefineWidth = 0;
    // Which patches the refinement asks midpoints of, with and without the rule.
    auto isSliver = [&](size_t patch) {
        const Patch& p = run.mesh.patches[patch];
        return 2 * p.area < options.minRefineWidth * p.diameter;
    };
    Gatherer::CornerSource corners = [&](size_t patch, int corner, double) {
        return run.lighting.solution.vertexIndirect[run.mesh.patches[patch].v[corner]];
    };
    for (double z : {0.121, 0.123, 0.125}) {
        const Vec3 at(1.0, 0.0, z), n(0, 1, 0);
        std::array<int, 2> sliverMidpoints{0, 0}, otherMidpoints{0, 0};
        std::array<double, 2> value{};
        for (int rule = 0; rule < 2; ++rule) {
            const Gatherer gatherer(run.scene, run.mesh, run.lighting.clustering, run.lighting.solution, *run.embree,
                                    rule ? options : everyStrip);
            Gatherer::MidpointSource midpoints = [&](size_t patch, uint64_t a, uint64_t b, const Vec3& y, double) {
                ++(isSliver(patch) ? sliverMidpoints : otherMidpoints)[rule];
                // The display's linear value: what matters here is who is asked.
                const Patch& p = run.mesh.patches[patch];
                const Vec3 w = barycentric(run.mesh.corner(p, 0), run.mesh.corner(p, 1), run.mesh.corner(p, 2), y);
                return Gatherer::Midpoint{
                    (a << 20) ^ b, weightedVertexIndirect(run.mesh, run.lighting.solution, patch, {w[0], w[1], w[2]})};
            };
            Gatherer::Request request(at, n, &corners, Gatherer::Threads::Serial);
            request.midpoints = &midpoints;
            value[rule] = luminance(gatherer.gatherWith(request));
        }
        INFO("z " << z << ": midpoints asked of slivers " << sliverMidpoints[0] << " → " << sliverMidpoints[1]
                  << ", of other patches " << otherMidpoints[0] << " → " << otherMidpoints[1] << "; " << value[0]
                  << " → " << value[1] << " lx");
        CHECK(sliverMidpoints[0] > 0);                  // the strips are near and were refined
        CHECK(sliverMidpoints[1] == 0);                 // now they are not
        CHECK(otherMidpoints[1] == otherMidpoints[0]);  // the floor and the wall as before
        CHECK(std::abs(value[1] / value[0] - 1) < 0.01);
    }
}
