// Seam vertices: which vertices take a point gather instead of the reconstruction.
#include <app/pipeline.h>

#include "test_support.h"

#include <fmt/format.h>

using namespace rayrad;

namespace {

/// A 4 m floor meshed at 1 m, with a 1 m box standing on it at x0..x0+1, z0..z0+1, lit
/// from above. The box has no bottom face: its four sides meet the floor.
std::string floorWithBox(double x0, double z0) {
    return fmt::format(R"({{"materials": {{"m": {{"reflectance": 0.5}}}},
        "objects": [
          {{"type": "quad", "material": "m", "vertices": [[0,0,0],[0,0,4],[4,0,4],[4,0,0]]}},
          {{"type": "quad", "material": "m", "vertices": [[{a},0,{c}],[{a},1,{c}],[{b},1,{c}],[{b},0,{c}]]}},
          {{"type": "quad", "material": "m", "vertices": [[{a},0,{d}],[{b},0,{d}],[{b},1,{d}],[{a},1,{d}]]}},
          {{"type": "quad", "material": "m", "vertices": [[{a},0,{c}],[{a},0,{d}],[{a},1,{d}],[{a},1,{c}]]}},
          {{"type": "quad", "material": "m", "vertices": [[{b},0,{c}],[{b},1,{c}],[{b},1,{d}],[{b},0,{d}]]}},
          {{"type": "quad", "material": "m", "vertices": [[{a},1,{c}],[{a},1,{d}],[{b},1,{d}],[{b},1,{c}]]}}],
        "lights": [{{"type": "point", "position": [2, 3, 3], "intensity_cd": 100}}],
        "radiosity": {{"max_edge": 1}}}})",
                       fmt::arg("a", x0), fmt::arg("b", x0 + 1), fmt::arg("c", z0), fmt::arg("d", z0 + 1));
}

app::PipelineOptions quiet() {
    app::PipelineOptions o;
    o.quiet = true;
    return o;
}

}  // namespace

TEST_CASE("seam vertices: a box standing on the floor's mesh lines has seams at its foot", "[solver]") {
    auto run = app::runPipeline(test::writeTempScene("box_on_grid", floorWithBox(1, 1)), quiet());
    // Each side face's two bottom corners (8) and the floor's 4 vertices at the box's
    // corners, which lie on the sides' bottom edges. A side face meshed at 1 m has no
    // other vertex there.
    CHECK(run.edgeVertices == 12);
}

TEST_CASE("seam vertices: a box standing between the floor's mesh lines has none", "[solver]") {
    // Shifted off the grid (and off the triangles' diagonals) the box's outline crosses
    // the floor's triangles: a floor vertex
    // next to the foot is not on the contact line, and gathering there would paint the
    // triangle around it with a value from the wrong side (the Cornell box's blotches).
    auto run = app::runPipeline(test::writeTempScene("box_off_grid", floorWithBox(1.3, 1.45)), quiet());
    CHECK(run.edgeVertices == 0);
}
