// The paper's empty cube end to end at 4 800 triangles: sensors and the photometric image.
#include <app/pipeline.h>

#include "test_support.h"

#include <cmath>

using namespace rayrad;

namespace {

/// One solve shared by the tests below (about 12 s on 2 cores).
const app::PipelineRun& cubeRun() {
    static const app::PipelineRun run = [] {
        app::PipelineOptions o;
        o.quiet = true;
        o.wantImage = true;
        o.overrides = {{"camera.resolution", "[33, 33]"}, {"render.spp", "4"}};
        return app::runPipeline(test::sourcePath("scenes/cube/cube.json"), o);
    }();
    return run;
}

}  // namespace

TEST_CASE("cube 4800: direct at A B C within 0.5% of Table 1", "[cube][slow]") {
    const auto& run = cubeRun();
    REQUIRE(run.mesh.patches.size() == 4800);
    REQUIRE(run.sensors.size() == 3);
    for (const auto& s : run.sensors) {
        INFO(s.sensor.name);
        CHECK(luminance(s.value.direct) == Approx(*s.sensor.refDirect).epsilon(0.005));
    }
}

TEST_CASE("cube 4800: gathered indirect at A B C within 2% of Table 1", "[cube][slow]") {
    for (const auto& s : cubeRun().sensors) {
        INFO(s.sensor.name << " gathered " << luminance(s.value.indirect) << " vertex "
                           << luminance(*s.value.indirectVertex) << " reference " << *s.sensor.refIndirect);
        CHECK(luminance(s.value.indirect) == Approx(*s.sensor.refIndirect).epsilon(0.02));
        CHECK(s.value.indirectVertex.has_value());
    }
}

TEST_CASE("cube 4800: the EXR pixel at A reads rho (E_dir + E_ind) / pi = 892.3 cd/m2 within 3%", "[cube][slow]") {
    const auto& run = cubeRun();
    REQUIRE(run.image);
    // 33×33 pixels: the centre pixel looks at A = (5, 5, 10).
    double L = luminance(run.image->at(16, 16));
    double expected = (2.0 / 3.0) * (2000.0 + 2205.1) / kPi;
    CHECK(expected == Approx(892.3).epsilon(1e-4));
    CHECK(L == Approx(expected).epsilon(0.03));
}

TEST_CASE("cube 4800: vertex values at A B C within 1.5% (seam vertices gathered)", "[cube][slow]") {
    const auto& run = cubeRun();
    // Every face's boundary vertices are on seams: 4 edges of 21 vertices at 0.5 m,
    // less the 4 corners counted twice, on each of the 6 faces.
    CHECK(run.lighting.displayVertices.seams == 6 * (4 * 21 - 4));
    CHECK(run.lighting.displayVertices.contacts == 0);
    for (const auto& s : run.sensors) {
        INFO(s.sensor.name << " vertex " << luminance(*s.value.indirectVertex) << " reference "
                           << *s.sensor.refIndirect);
        REQUIRE(s.value.indirectVertex.has_value());
        CHECK(luminance(*s.value.indirectVertex) == Approx(*s.sensor.refIndirect).epsilon(0.015));
    }
}
