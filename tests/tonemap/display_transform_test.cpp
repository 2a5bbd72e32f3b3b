// The embedded OCIO config: sRGB encoding, the ACES view, and exposure.
#include <core/input_error.h>
#include <tonemap/display_transform.h>

#include "test_support.h"

#include <cmath>

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

namespace {
/// The inverse of the piecewise sRGB curve (IEC 61966-2-1): code value → display linear.
double srgbToLinear(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }
}  // namespace

TEST_CASE("the embedded ACES 1.0 view: mid grey at 10 % of display white, neutrals neutral, highlights rolled off",
          "[tonemap]") {
    tonemap::DisplayOptions o;
    o.view = "ACES 1.0 SDR-video";
    CHECK(tonemap::viewToneCurve(o) == "ACES 1.0 SDR-video");
    const auto out = tonemap::displayEncode({0.18f, 0.18f, 0.18f, 16.0f, 16.0f, 16.0f, 4.0f, 0.1f, 0.1f}, o);
    // ACES 1.0 SDR video: scene 0.18 → 4.8 of the reference rendering's 48 cd/m² cinema
    // white, i.e. 10 % of display white, raised by the dim-surround gamma 0.9811:
    // 0.0996^0.9811 = 0.104.
    CHECK(srgbToLinear(out[0]) == Approx(0.104).epsilon(0.02));
    CHECK(out[1] == Approx(out[0]).margin(1e-4));  // D65 grey stays grey (D60 ↔ D65 adaptation undone)
    CHECK(out[2] == Approx(out[0]).margin(1e-4));
    // 16 × mid grey is still below display white (the Standard view clips at 1 already).
    CHECK(out[3] > 0.99);
    CHECK(out[3] <= 1.001);
    // A red four times brighter than white stays red: R well above G and B.
    CHECK(out[6] > 0.95);
    CHECK(out[7] < 0.6);
    CHECK(out[8] < 0.6);
    tonemap::DisplayOptions standard;
    CHECK(tonemap::viewToneCurve(standard).empty());
}

TEST_CASE("a view with its own tone curve gets scene-referred values, and a second tone curve is a warning", "[tonemap]") {
    HdrImage img(2, 1);
    img.at(0, 0) = Rgb(100.0);
    img.at(1, 0) = Rgb(6400.0);  // 8 × the log-average 800: 1.44 after auto exposure, above display white
    tonemap::DisplayOptions standard;
    tonemap::DisplayOptions aces;
    aces.view = "ACES 1.0 SDR-video";
    const auto s = tonemap::toDisplay(img, standard);
    const auto a = tonemap::toDisplay(img, aces);
    CHECK(s[3] == 255);  // 1.44 → scaled into the gamut, 1.0
    CHECK(a[3] < 245);   // the ACES curve sees 1.44 and rolls it off below white
    CHECK(a[3] > a[0]);
    CHECK_FALSE(tonemap::checkDisplayOptions(aces).has_value());
    aces.tone.op = tonemap::ToneOperator::Reinhard;
    const auto warning = tonemap::checkDisplayOptions(aces);
    REQUIRE(warning.has_value());
    CHECK_THAT(*warning, Catch::Contains("two tone curves"));
    CHECK_FALSE(tonemap::checkDisplayOptions(standard).has_value());
}
