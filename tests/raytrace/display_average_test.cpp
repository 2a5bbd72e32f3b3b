// Antialiasing that survives display: display images average a pixel's samples
// after range compression, so a lamp's edge shades off over its pixels; the EXR keeps the
// plain average.
#include <app/pipeline.h>
#include <tonemap/display_transform.h>

#include "pipeline_test_util.h"
#include "test_support.h"

#include <catch2/catch.hpp>
#include <fmt/format.h>

using namespace rayrad;

namespace {

/// A grey room seen from below a bright ceiling panel (20 000 cd/m², tilted 20° about z
/// so its edges cross the pixel grid), 48 × 48 at 16 spp.
app::PipelineRun lampRoom(bool compression) {
    const std::string json = fmt::format(R"({{"materials": {{"w": {{"reflectance": 0.5}},
            "lamp": {{"type": "emissive", "luminance_cd_m2": 20000}}}},
        "objects": [{{"type": "box", "min": [0, 0, 0], "max": [3, 2.5, 3], "facing": "inward", "material": "w"}},
                    {{"type": "quad", "material": "lamp", "vertices": [[1.1, 2.49, 1.3], [1.9, 2.49, 1.0], [1.9, 2.49, 1.7], [1.1, 2.49, 2.0]]}}],
        "camera": {{"position": [1.5, 0.3, 1.5], "look_at": [1.5, 2.5, 1.5], "up": [0, 0, 1], "vfov_deg": 50, "resolution": [48, 48]}},
        "radiosity": {{"max_edge": 0.5}}, "render": {{"spp": 16, "display_range_compression": {}}}}})",
                                         compression ? "true" : "false");
    app::PipelineOptions options = test::quiet();
    options.wantImage = true;
    return app::runPipeline(test::writeTempScene(compression ? "lamp_room_compressed" : "lamp_room_plain", json), options);
}

/// The lamp's edge pixels (partly covered: between 2 % and 98 % of its luminance in the
/// plain average `exr`) whose display luminance is not white: the edge's shades.
int shades(const HdrImage& display, const HdrImage& exr) {
    int n = 0;
    const std::vector<Rgb> shown = tonemap::toDisplayLinear(display, tonemap::DisplayOptions{});
    for (size_t i = 0; i < shown.size(); ++i) {
        const double lamp = luminance(exr.pixels[i]) / 20000;  // the part of the pixel the lamp covers
        if (lamp > 0.02 && lamp < 0.98 && luminance(shown[i]) < 0.97) ++n;
    }
    return n;
}

}  // namespace

TEST_CASE("a lamp's edge shades off in the display image and the EXR's average is untouched", "[image]") {
    const auto compressed = lampRoom(true), plain = lampRoom(false);
    REQUIRE(compressed.displayImage);
    // The radiance image does not depend on the option.
    CHECK(compressed.image->pixels == plain.image->pixels);
    const int withCompression = shades(*compressed.displayImage, *compressed.image),
              withoutCompression = shades(*plain.displayImage, *plain.image);
    WARN("edge pixels between dark and white: " << withCompression << " with range compression, " << withoutCompression
                                                 << " with the plain average");
    CHECK(withCompression > 2 * withoutCompression + 10);
    // A pixel of one level is the same in both.
    CHECK(luminance(compressed.displayImage->at(0, 0)) == Approx(luminance(compressed.image->at(0, 0))).epsilon(0.05));
}
