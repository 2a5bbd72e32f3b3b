// Projections: a 180° fisheye at a sensor sees the light that reaches it, so
// the image integrated over the hemisphere, Σ L cos θ dω, is the sensor's indirect
// illuminance (the point light itself is not in the picture); orthographic rays are
// parallel.
#include <app/pipeline.h>
#include <raytrace/camera.h>

#include "pipeline_test_util.h"
#include "test_support.h"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <cmath>

using namespace rayrad;

TEST_CASE("a fisheye view from a sensor integrates to the sensor's indirect illuminance", "[image]") {
    const std::string json = R"({"materials": {"w": {"reflectance": 0.6}},
        "objects": [{"type": "box", "min": [0, 0, 0], "max": [4, 2.8, 3], "facing": "inward", "material": "w"},
                    {"type": "box", "min": [2.5, 0, 0.5], "max": [3.5, 0.75, 1.5], "material": "w"}],
        "lights": [{"type": "point", "position": [1.2, 2.5, 1.8], "intensity_cd": 300}],
        "sensors": [{"name": "floor", "position": [1.5, 0, 1.2], "normal": [0, 1, 0]}],
        "cameras": [{"name": "fish", "projection": "fisheye", "from_sensor": "floor", "resolution": [160, 160]}],
        "radiosity": {"max_edge": 0.25}, "render": {"spp": 4}})";
    app::PipelineOptions options = test::quiet();
    options.wantImage = true;
    const auto run = app::runPipeline(test::writeTempScene("fisheye_sensor", json), options);
    REQUIRE(run.image);
    const HdrImage& img = *run.image;
    // Equidistant: θ = (r / R) π/2; a pixel covers dω = (sin θ / θ) (π / 2R)² sr.
    const double R = img.width / 2.0, step = kPi / (2 * R);
    double E = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const double r = std::hypot(x + 0.5 - R, y + 0.5 - R) / R;
            if (r > 1) continue;
            const double theta = r * kPi / 2, sinc = theta > 0 ? std::sin(theta) / theta : 1.0;
            E += luminance(img.at(x, y)) * std::cos(theta) * sinc * step * step;
        }
    const double indirect = luminance(run.sensors[0].value.indirect);
    WARN("fisheye integral " << E << " lx, sensor indirect " << indirect << " lx");
    CHECK(E == Approx(indirect).epsilon(0.03));
    // Outside the circle: black.
    CHECK(img.at(0, 0) == Rgb(0.0));
}

TEST_CASE("orthographic rays are parallel and cover height_m", "[image]") {
    scene::Camera c;
    c.position = Vec3(2, 10, 1.5);
    c.lookAt = Vec3(2, 0, 1.5);
    c.up = Vec3(0, 0, -1);
    c.width = 40, c.height = 30;
    c.projection = scene::Projection::Orthographic;
    c.orthoHeight = 3;
    const raytrace::ImageCamera cam(c);
    const auto corner = cam.ray(0, 0), other = cam.ray(40, 30);
    CHECK(corner.direction == Vec3(0, -1, 0));
    CHECK(other.direction == Vec3(0, -1, 0));
    CHECK(glm::length(other.origin - corner.origin) == Approx(std::hypot(4.0, 3.0)));  // 4 × 3 m
}
