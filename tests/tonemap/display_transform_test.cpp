// The embedded OCIO config: sRGB encoding and exposure.
#include <core/input_error.h>
#include <tonemap/display_transform.h>

#include "test_support.h"

using namespace rayrad;

TEST_CASE("the embedded config encodes scene-linear 0.18 as sRGB 0.4614", "[tonemap]") {
    tonemap::DisplayOptions o;
    auto out = tonemap::displayEncode({0.18f, 0.18f, 0.18f, 1.0f, 0.0f, 0.001f}, o);
    CHECK(out[0] == Approx(0.4614).margin(5e-4));
    CHECK(out[3] == Approx(1.0).margin(1e-5));
    CHECK(out[4] == Approx(0.0).margin(1e-6));
    CHECK(out[5] == Approx(12.92 * 0.001).margin(2e-4));  // the linear toe of the sRGB curve
}

TEST_CASE("auto exposure maps the log-average luminance to 0.18", "[tonemap]") {
    HdrImage img(2, 1);
    img.at(0, 0) = Rgb(100.0);
    img.at(1, 0) = Rgb(400.0);
    tonemap::DisplayOptions o;
    CHECK(tonemap::exposureScale(img, o) == Approx(0.18 / 200.0));
    o.exposureStops = 1;
    CHECK(tonemap::exposureScale(img, o) == Approx(0.36 / 200.0));
    o.autoExposure = false;
    o.exposureStops = -3;
    CHECK(tonemap::exposureScale(img, o) == Approx(0.125));
}

TEST_CASE("an unknown display or a missing config is a clear input error", "[tonemap]") {
    tonemap::DisplayOptions o;
    o.display = "nonexistent";
    CHECK_THROWS_AS(tonemap::displayEncode({0.1f, 0.1f, 0.1f}, o), InputError);
    tonemap::DisplayOptions p;
    p.ocioConfig = "/nonexistent/config.ocio";
    CHECK_THROWS_AS(tonemap::displayEncode({0.1f, 0.1f, 0.1f}, p), InputError);
}
