// Shading normals (no mesh facets in images): a coarse sphere's facets
// show in flat shading and not with interpolated normals; a mesh of sharp edges (a
// tetrahedron, creases of 70.5°) renders exactly as flat shading does; the radiosity
// (sensors) is the same either way.
#include <app/pipeline.h>

#include "pipeline_test_util.h"
#include "test_support.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace rayrad;

namespace {

/// Σ |L(x−1) − 2 L(x) + L(x+1)| over the rows, inside the lit part (all of x ± 3 lit): the
/// kinks that facet edges put into the shading.
double kinks(const HdrImage& img) {
    double sum = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 3; x + 3 < img.width; ++x) {
            bool inside = true;
            for (int d = -3; d <= 3; ++d) inside &= luminance(img.at(x + d, y)) > 0;
            if (!inside) continue;
            const double a = luminance(img.at(x - 1, y)), b = luminance(img.at(x, y)), c = luminance(img.at(x + 1, y));
            sum += std::abs(a - 2 * b + c);
        }
    return sum;
}

app::PipelineRun render(const std::string& name, const std::string& json, const std::string& angle) {
    app::PipelineOptions o = test::quiet({{"render.smoothing_angle_deg", angle}});
    o.wantImage = true;
    return app::runPipeline(test::writeTempScene(name, json), o);
}

}  // namespace

TEST_CASE("a coarse sphere's facets show in flat shading, not with shading normals", "[image]") {
    const std::string json = R"({"materials": {"m": {"reflectance": 0.5}},
        "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "subdivisions": 6, "material": "m"}],
        "lights": [{"type": "point", "position": [3, 4, 5], "intensity_cd": 1000}],
        "sensors": [{"name": "s", "position": [0, 1, 0], "normal": [0, 1, 0]}],
        "camera": {"position": [0, 0, 4], "look_at": [0, 0, 0], "vfov_deg": 35, "resolution": [96, 96]},
        "render": {"spp": 4}})";
    const auto flat = render("sphere_flat", json, "0");
    const auto smooth = render("sphere_smooth", json, "30");
    CHECK(flat.mesh.cornerNormal.empty());
    CHECK(!smooth.mesh.cornerNormal.empty());
    const double kf = kinks(*flat.image), ks = kinks(*smooth.image);
    INFO("kinks: flat " << kf << ", smooth " << ks);
    CHECK(ks < 0.5 * kf);
    // Images only: the solution and sensors do not change.
    CHECK(luminance(smooth.sensors[0].value.direct) == luminance(flat.sensors[0].value.direct));
    CHECK(luminance(smooth.sensors[0].value.indirect) == luminance(flat.sensors[0].value.indirect));
}

TEST_CASE("sharp edges stay sharp: a tetrahedron renders as with flat shading", "[image]") {
    const std::string json = R"({"materials": {"m": {"reflectance": 0.5}},
        "objects": [{"type": "mesh", "file": ")" + test::sourcePath("tests/data/tetrahedron.obj") + R"(", "material": "m"}],
        "lights": [{"type": "point", "position": [3, 4, 5], "intensity_cd": 1000}],
        "camera": {"position": [2, 1.5, 3], "look_at": [0.3, 0.3, 0.3], "resolution": [64, 64]},
        "render": {"spp": 2}})";
    const auto flat = render("tetra_flat", json, "0");
    const auto smooth = render("tetra_smooth", json, "30");
    CHECK(smooth.mesh.cornerNormal.empty());  // every crease is sharper than 30°
    CHECK(smooth.image->pixels == flat.image->pixels);
}
