// Scenes nobody here made (bench/corpus/): the small ones run in the default tests with
// their defaults, as a user would run them. bench/corpus.sh runs them all with the figures.
#include <app/pipeline.h>

#include "pipeline_test_util.h"
#include "test_support.h"

#include <cmath>

using namespace rayrad;

namespace {

/// Every sensor on a surface: what an image shows there (the mesh) against the final
/// gather, within `tolerance` of the gather's total (direct + indirect).
void checkMeshAgainstGather(const app::PipelineRun& run, double tolerance) {
    for (const auto& r : run.sensors) {
        const auto& v = r.value;
        if (!v.indirectVertex) continue;
        const double mesh = luminance(*v.indirectVertex), gathered = luminance(v.indirect),
                     total = luminance(v.direct) + gathered;
        INFO(r.sensor.name << ": mesh " << mesh << " lx, gathered " << gathered << " lx of " << total << " lx");
        CHECK(std::abs(mesh - gathered) <= tolerance * total);
    }
}

}  // namespace

TEST_CASE(
    "corpus: a Cornell box from a CAD exporter (walls 0.3 mm thick, the lamp's sides emitting into the gap) "
    "creates no light",
    "[real_scenes][corpus]") {
    // The inner walls and the box's outer shell face each other 0.3 mm apart (pieces of the
    // two lie in one plane, facing the same way): the secondary pass created +32 % of the
    // emitted light before a shot's deliveries were capped at what it ships.
    auto run = app::runPipeline(test::sourcePath("bench/corpus/iset-cornell-lamp/scene.json"), test::quiet());
    const auto balance = app::energyBalanceOf(run);
    INFO("not accounted " << 100 * balance.relativeError() << " % (direct pass " << 100 * balance.directError()
                          << " %, secondary pass " << 100 * balance.secondaryError() << " %)");
    CHECK(run.lighting.shooting.cappedShots > 0);
    // The front is open: light escapes (negative), none may be created.
    CHECK(balance.secondaryError() < 0.005);
    CHECK(balance.directError() < 0.005);
    checkMeshAgainstGather(run, 0.05);
}

TEST_CASE("corpus: McGuire's Cornell box as its OBJ and MTL come creates no light", "[real_scenes][corpus]") {
    auto run = app::runPipeline(test::sourcePath("bench/corpus/mcguire-cornell/scene.json"), test::quiet());
    const auto balance = app::energyBalanceOf(run);
    INFO("not accounted " << 100 * balance.relativeError() << " % (direct pass " << 100 * balance.directError()
                          << " %, secondary pass " << 100 * balance.secondaryError() << " %)");
    CHECK(balance.secondaryError() < 0.005);
    CHECK(balance.directError() < 0.005);
}
