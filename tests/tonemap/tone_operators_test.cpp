// Tone reproduction and white balance: the operators against their published
// equations, worked by hand; luminance and chroma kept apart; Bradford white balance.
#include <app/pipeline.h>
#include <core/colour_temperature.h>
#include <core/input_error.h>
#include <tonemap/display_transform.h>

#include "pipeline_test_util.h"
#include "test_support.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace rayrad;
using namespace rayrad::tonemap;

namespace {

/// A row of grey pixels of the given luminances (cd/m²).
HdrImage greys(std::initializer_list<double> values) {
    HdrImage img(static_cast<int>(values.size()), 1);
    int x = 0;
    for (double v : values) img.at(x++, 0) = Rgb(v);
    return img;
}

/// CIELAB hue angle (degrees) of a linear Rec.709 colour (D65 white).
double hueAngle(const Rgb& c) {
    const double X = 0.4124564 * c.r + 0.3575761 * c.g + 0.1804375 * c.b;
    const double Y = 0.2126729 * c.r + 0.7151522 * c.g + 0.0721750 * c.b;
    const double Z = 0.0193339 * c.r + 0.1191920 * c.g + 0.9503041 * c.b;
    auto f = [](double t) { return t > 216.0 / 24389 ? std::cbrt(t) : (24389.0 / 27 * t + 16) / 116; };
    const double fx = f(X / 0.95047), fy = f(Y / 1.0), fz = f(Z / 1.08883);
    return std::atan2(200 * (fy - fz), 500 * (fx - fy)) * 180 / kPi;
}

}  // namespace

TEST_CASE("Reinhard 2002 at worked values: the average to the key, the largest to white", "[tonemap]") {
    // L̄_w = exp(mean ln{1, 10, 100}) = 10; L = 0.18 L_w / 10 = 0.018, 0.18, 1.8; L_white = 1.8.
    ToneOptions o;
    o.op = ToneOperator::Reinhard;
    const ToneCurve curve(greys({1, 10, 100}), o, 1.0);
    CHECK(curve(100) == Approx(1.0).epsilon(1e-12));                          // 1.8 (1 + 1.8/3.24) / 2.8
    CHECK(curve(10) == Approx(0.18 * (1 + 0.18 / 3.24) / 1.18).epsilon(1e-12)); // 0.161017
    CHECK(curve(10) == Approx(0.161017).epsilon(1e-5));
    CHECK(curve(1) == Approx(0.018 * (1 + 0.018 / 3.24) / 1.018).epsilon(1e-12));
    o.white = 1e9;  // L_white → ∞: L / (1 + L)
    CHECK(ToneCurve(greys({1, 10, 100}), o, 1.0)(100) == Approx(1.8 / 2.8).epsilon(1e-9));
}

TEST_CASE("Ward 1994 at worked values: sf = [(1.219 + (Ldmax/2)^0.4) / (1.219 + Lwa^0.4)]^2.5", "[tonemap]") {
    ToneOptions o;
    o.op = ToneOperator::Ward;
    o.worldAdaptation = 10;
    o.displayMax = 100;
    // (1.219 + 50^0.4) / (1.219 + 10^0.4) = 6.00078 / 3.73089; ^2.5 = 3.280847.
    const ToneCurve curve(greys({1}), o, 1.0);
    CHECK(curve(10) == Approx(3.280847 * 10 / 100).epsilon(1e-6));
    CHECK(curve(20) == Approx(2 * curve(10)).epsilon(1e-12));  // a linear scale: contrast kept
}

TEST_CASE("Tumblin-Rushmeier (revised) at worked values: Stevens' exponents and the contrast factor", "[tonemap]") {
    ToneOptions o;
    o.op = ToneOperator::TumblinRushmeier;
    o.worldAdaptation = 10;  // L_da = L_dmax / 2 = 50, C_max = 100
    o.displayMax = 100;
    // γ(10) = 1.855 + 0.4 log10(10.000023) = 2.255000; γ(50) = 2.534588;
    // γ_wd = 2.255000 / 2.534588 = 0.889691; m = 100^((γ_wd − 1)/2) = 0.775695.
    const ToneCurve curve(greys({1}), o, 1.0);
    CHECK(curve(10) == Approx(0.775695 * 50 / 100).epsilon(1e-6));   // L_w = L_wa → m L_da
    CHECK(curve(100) == Approx(3.008515).epsilon(1e-6));            // m L_da 10^(γ_w/γ_d) / L_dmax
    // Bright world (γ = 2.655 above 100 cd/m²).
    o.worldAdaptation = 1000;
    const double gwd = 2.655 / 2.534588;
    CHECK(ToneCurve(greys({1}), o, 1.0)(1000) == Approx(std::pow(100.0, (gwd - 1) / 2) * 0.5).epsilon(1e-6));
}

TEST_CASE("luminance and chroma apart: a bright red stays red, in gamut, luminance kept where it can be", "[tonemap]") {
    // A saturated red whose luminance the display can show with less chroma: luminance and hue kept.
    const Rgb red(1.3, 0.25, 0.2);
    const Rgb shown = toDisplayGamut(red);
    CHECK(std::max({shown.r, shown.g, shown.b}) <= 1.0);
    CHECK(luminance(shown) == Approx(luminance(red)).epsilon(1e-3));
    CHECK(std::abs(hueAngle(shown) - hueAngle(red)) < 2.0);
    // Brighter than display white: still red (per-channel clipping gives (1, 1, 1) here).
    const Rgb bright = red * 8.0;
    const Rgb shownBright = toDisplayGamut(bright);
    CHECK(std::abs(hueAngle(shownBright) - hueAngle(red)) < 2.0);
    CHECK(shownBright.r > 1.5 * shownBright.g);
    CHECK(std::max({shownBright.r, shownBright.g, shownBright.b}) == Approx(1.0));
    // In gamut: untouched.
    CHECK(toDisplayGamut(Rgb(0.3, 0.5, 0.1)) == Rgb(0.3, 0.5, 0.1));
    // Through the whole chain: a red surface at 5 × the exposure's white stays red.
    HdrImage img = greys({10, 10, 10});
    img.at(1, 0) = Rgb(0.8, 0.1, 0.08) * 500.0;
    DisplayOptions d;
    d.autoExposure = false;
    d.exposureStops = std::log2(1 / 100.0);  // 100 cd/m² is white
    const auto linear = toDisplayLinear(img, d);
    CHECK(std::abs(hueAngle(linear[1]) - hueAngle(Rgb(0.8, 0.1, 0.08))) < 2.0);
}

TEST_CASE("white balance by Bradford: a 3000 K white becomes neutral, grey world and a region likewise", "[tonemap]") {
    const Rgb warm = colourOfTemperature(3000);  // luminance 1
    HdrImage img(10, 10);
    for (auto& p : img.pixels) p = warm * 50.0;
    img.at(9, 9) = Rgb(0.9, 0.05, 0.05) * 50.0;  // one red pixel
    for (const char* how : {"3000K", "grey-world", "region:0,0,2,2"}) {
        INFO(how);
        const WhiteBalance wb = parseWhiteBalance(how);  // grey world: one red pixel in 100 tints the mean a little
        const Matrix3 m = whiteBalanceMatrix(img, wb);
        const Rgb balanced = applyMatrix(m, warm * 50.0);
        const double tolerance = std::string(how) == "grey-world" ? 0.03 : 1e-9;  // the red pixel tints the mean
        CHECK(balanced.r == Approx(balanced.g).epsilon(tolerance));
        CHECK(balanced.b == Approx(balanced.g).epsilon(tolerance));
        CHECK(luminance(balanced) == Approx(50.0).epsilon(std::max(tolerance, 1e-3)));
    }
    CHECK(applyMatrix(whiteBalanceMatrix(img, parseWhiteBalance("none")), warm) == warm);
    // D65 lies 0.003 Δuv off the Planckian locus: balancing from 6504 K changes a grey by a few %.
    const Rgb grey = applyMatrix(whiteBalanceMatrix(img, parseWhiteBalance("6504K")), Rgb(0.5));
    CHECK(grey.r == Approx(0.5).epsilon(0.06));
    CHECK(grey.b == Approx(0.5).epsilon(0.06));
    CHECK(luminance(grey) == Approx(0.5).epsilon(0.01));
    CHECK_THROWS_WITH(whiteBalanceMatrix(img, parseWhiteBalance("region:9,1,2,2")), Catch::Contains("is not inside the 10×10 image"));
    CHECK_THROWS_WITH(parseWhiteBalance("warm"), Catch::Contains("--white-balance: expected none, a colour temperature"));
    CHECK_THROWS_WITH(parseWhiteBalance("900K"), Catch::Contains("from 1667 to 25000 K"));
    CHECK_THROWS_WITH(parseWhiteBalance("region:1,2,0,3"), Catch::Contains("width and height positive"));
    CHECK_THROWS_WITH(parseToneOperator("aces"), Catch::Contains("--tonemap: expected exposure"));
}

TEST_CASE("a white room rendered: display luminance of its walls under each operator", "[tonemap]") {
    // A 4 × 3 × 5 m room, walls ρ = 0.8, lit by a point light: as a user renders it.
    const std::string json = R"({"materials": {"white": {"reflectance": 0.8}},
        "objects": [{"type": "box", "min": [0, 0, 0], "max": [4, 3, 5], "facing": "inward", "material": "white"}],
        "lights": [{"type": "point", "position": [2, 2.8, 2.5], "intensity_cd": 3000}],
        "camera": {"position": [2, 1.5, 4.8], "look_at": [2, 1.2, 0], "vfov_deg": 70, "resolution": [64, 48]},
        "radiosity": {"max_edge": 0.5}})";
    app::PipelineOptions options = test::quiet();
    options.wantImage = true;
    const auto run = app::runPipeline(test::writeTempScene("white_room", json), options);
    auto meanDisplayLuminance = [&](ToneOperator op) {
        DisplayOptions d;
        d.tone.op = op;
        double sum = 0;
        for (const Rgb& p : toDisplayLinear(*run.image, d)) sum += luminance(p);
        return sum / static_cast<double>(run.image->pixels.size());
    };
    const double world = logAverageLuminance(*run.image);
    const double exposure = meanDisplayLuminance(ToneOperator::Exposure), ward = meanDisplayLuminance(ToneOperator::Ward),
                 tr = meanDisplayLuminance(ToneOperator::TumblinRushmeier),
                 reinhard = meanDisplayLuminance(ToneOperator::Reinhard);
    WARN("white room, L_wa " << world << " cd/m2: mean display luminance exposure " << exposure << ", ward " << ward
                              << ", tumblin-rushmeier " << tr << ", reinhard " << reinhard);
    CHECK(exposure == Approx(0.18).epsilon(0.2));  // the key: mid-grey, the complaint
    CHECK(ward > 0.7);                             // the absolute level: a bright white room shows bright
    CHECK(tr > 0.5);
}
