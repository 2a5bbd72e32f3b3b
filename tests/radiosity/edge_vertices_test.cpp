// Seam vertices: which vertices take a point gather instead of the reconstruction.
#include <app/pipeline.h>
#include <radiosity/gather.h>

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

TEST_CASE("seam vertices: a box standing on the floor has the same seams on and off the floor's grid", "[solver]") {
    // The premesher cuts the floor along the box's foot (contact lines), wherever it
    // stands, so the floor's vertices along the foot are seam vertices in both cases:
    // each side face's two bottom corners (8) and the floor's vertex copies at the foot's
    // corners, one for each side of the foot they belong to (12; the copies under the
    // box face the box's open bottom, not a side). Before the cut, a box off the grid
    // crossed the floor's triangles and had no seam at all: light from under the box
    // and beside it was averaged into one vertex.
    auto onGrid = app::runPipeline(test::writeTempScene("box_on_grid", floorWithBox(1, 1)), quiet());
    auto offGrid = app::runPipeline(test::writeTempScene("box_off_grid", floorWithBox(1.3, 1.45)), quiet());
    CHECK(onGrid.edgeVertices == 20);
    CHECK(offGrid.edgeVertices == 20);
    bool cornerVertex = false;
    for (const auto& v : offGrid.mesh.vertices) cornerVertex |= glm::length(v - Vec3(1.3, 0, 1.45)) < 1e-9;
    CHECK(cornerVertex);
}

TEST_CASE("seam vertices: a gather's near part and the rest add up to the whole gather", "[solver]") {
    // The seam rounds after the first gather only the near patches' part again (the part
    // the iterated corner values change) and keep the rest: the two must sum to the gather.
    // Meshed at 0.25 m, so that a point has both near patches and farther ones.
    std::string scene = floorWithBox(1.3, 1.45);
    const std::string coarse = R"("max_edge": 1)";
    scene.replace(scene.find(coarse), coarse.size(), R"("max_edge": 0.25)");
    auto run = app::runPipeline(test::writeTempScene("box_parts", scene), quiet());
    radiosity::GatherOptions options;
    options.levels = 3;
    options.farDiameters = 3;
    radiosity::Gatherer gatherer(run.scene, run.mesh, run.clustering, run.solution, *run.embree, options);
    radiosity::Gatherer::CornerSource corners = [&](size_t patch, int corner, double) {
        return run.solution.vertexIndirect[run.mesh.patches[patch].v[corner]];
    };
    using Part = radiosity::Gatherer::Part;
    // On the floor a hair beside the box's foot, at two of its sides.
    for (const Vec3 x : {Vec3(1.29, 1e-9, 1.9), Vec3(2.0, 1e-9, 2.46)}) {
        const Vec3 n(0, 1, 0);
        const Rgb all = gatherer.gatherWith(x, n, &corners, false, nullptr, 1, Part::All);
        const Rgb near = gatherer.gatherWith(x, n, &corners, false, nullptr, 1, Part::Near);
        const Rgb rest = gatherer.gatherWith(x, n, &corners, false, nullptr, 1, Part::AllButNear);
        CHECK(luminance(near) > 0);
        CHECK(luminance(rest) > 0);
        CHECK(luminance(near + rest) == Approx(luminance(all)).epsilon(1e-12));
    }
}
