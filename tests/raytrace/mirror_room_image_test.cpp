// Mirrors in images: what the image method adds to the radiosity shows in the rendering.
#include <app/pipeline.h>
#include <raytrace/camera.h>

#include "pipeline_test_util.h"
#include "test_support.h"

using namespace rayrad;

TEST_CASE("mirror room: the block face toward the mirror is brighter with mirrors considered", "[mirrors][image]") {
    // The paper's Fig. 10: the spots aim at the mirror, away from the block; only their
    // images light the block's face toward the mirror. Compare the pixel that sees it.
    auto render = [](const char* mode) {
        app::PipelineOptions o = test::quiet({{"camera.resolution", "[64, 48]"},
                                              {"render.spp", "4"},
                                              {"radiosity.max_edge", "0.4"},
                                              {"radiosity.mirrors", mode}});
        o.wantImage = true;
        o.wantSensors = false;
        return app::runPipeline(test::sourcePath("scenes/mirror_room/mirror_room.json"), o);
    };
    auto with = render("image"), without = render("ignore");
    REQUIRE(with.image);
    REQUIRE(without.image);
    // The pixel whose ray points closest to the face's centre (2, 0.4, 2).
    raytrace::ImageCamera camera(*with.scene.camera);
    Vec3 target = glm::normalize(Vec3(2, 0.4, 2) - with.scene.camera->position);
    int bx = 0, by = 0;
    double best = -1;
    for (int y = 0; y < camera.height(); ++y)
        for (int x = 0; x < camera.width(); ++x) {
            double d = glm::dot(camera.ray(x + 0.5, y + 0.5).direction, target);
            if (d > best) best = d, bx = x, by = y;
        }
    double lit = luminance(with.image->at(bx, by)), unlit = luminance(without.image->at(bx, by));
    INFO("pixel (" << bx << ", " << by << "): " << lit << " cd/m² with mirrors, " << unlit << " without");
    CHECK(lit > 3 * unlit);
}
