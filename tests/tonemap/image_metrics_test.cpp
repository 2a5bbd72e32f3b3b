// rayrad compare's figures: the exposure and per-channel factors recovered from
// a fake photograph, relative errors, log RMS and SSIM.
#include <core/colour_temperature.h>
#include <core/random.h>
#include <tonemap/image_alignment.h>
#include <tonemap/image_io.h>
#include <tonemap/image_metrics.h>

#include "test_support.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>

using namespace rayrad;
using namespace rayrad::tonemap;

namespace {

/// A test scene's luminance: smooth shading, a few coloured patches, a bright "lamp".
HdrImage scene(int w, int h) {
    HdrImage img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double shade = 20 + 60 * x / double(w) + 30 * std::sin(y * 0.2);
            Rgb c(0.7, 0.65, 0.6);
            if (x > w / 2 && y < h / 3) c = Rgb(0.7, 0.15, 0.1);
            if (x < w / 4 && y > h / 2) c = Rgb(0.15, 0.5, 0.2);
            img.at(x, y) = c * shade;
        }
    return img;
}

/// Linear → 8-bit sRGB → linear, as a camera's JPEG would store it (values already in [0, 1]).
double quantised(double v) {
    v = std::clamp(v, 0.0, 1.0);
    const double e = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
    return std::round(e * 255) / 255;
}

}  // namespace

TEST_CASE("a fake photograph: exposure ×1.7, a white-balance shift, noise and 8 bits give the factors back within 1 %",
          "[compare]") {
    const HdrImage rendering = scene(96, 64);
    const Rgb shift(1.08, 1.0, 0.86);  // a warmer camera white
    HdrImage photo(96, 64);
    Random rng(3, 1);
    const double toDisplay = 1.0 / 200;  // the photo's exposure maps 200 cd/m² to its white
    for (size_t i = 0; i < photo.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double noisy = rendering.pixels[i][c] * 1.7 * shift[c] * (1 + 0.02 * (rng.nextDouble() - 0.5));
            photo.pixels[i][c] = quantised(noisy * toDisplay);
        }
    const HdrImage decoded = linearFromSrgb(photo);
    const Region whole{"image", 0, 0, 96, 64};
    const auto k = channelFactors(rendering, decoded, whole);
    for (int c = 0; c < 3; ++c) {
        INFO("channel " << c);
        CHECK(k[c] / toDisplay == Approx(1.7 * shift[c]).epsilon(0.01));
    }
    // Calibrated per channel, the luminance errors in regions are small.
    HdrImage calibrated = rendering;
    for (auto& p : calibrated.pixels)
        for (int c = 0; c < 3; ++c) p[c] *= k[c];
    for (const Region& r : {whole, Region{"red", 60, 2, 30, 15}, Region{"green", 2, 40, 20, 20}}) {
        INFO(r.name);
        const ErrorFigures f = compareImages(calibrated, decoded, r);
        CHECK(std::abs(f.meanRelPct) < 2.0);
        CHECK(f.medianAbsRelPct < 2.0);
        CHECK(f.ssim > 0.95);
    }
    // One exposure factor for a grey-dominated image: near the luminance ratio.
    CHECK(exposureFactor(rendering, decoded, whole) / toDisplay == Approx(1.7).epsilon(0.03));
}

TEST_CASE("an image against itself: no error and SSIM 1, against a shifted copy SSIM falls", "[compare]") {
    const HdrImage a = scene(48, 32);
    const Region whole{"image", 0, 0, 48, 32};
    const ErrorFigures same = compareImages(a, a, whole);
    CHECK(same.meanAbsRelPct == 0);
    CHECK(same.rmsLog == 0);
    CHECK(same.ssim == Approx(1.0));
    CHECK(exposureFactor(a, a, whole) == Approx(1.0));
    HdrImage shifted = a;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 48; ++x) shifted.at(x, y) = a.at((x + 6) % 48, y);
    const ErrorFigures moved = compareImages(shifted, a, whole);
    CHECK(moved.ssim < 0.95);
    CHECK(moved.meanAbsRelPct > 5);
    // 10 % brighter everywhere: +10 % mean, ln 1.1 RMS.
    HdrImage brighter = a;
    for (auto& p : brighter.pixels) p *= 1.1;
    const ErrorFigures b = compareImages(brighter, a, whole);
    CHECK(b.meanRelPct == Approx(10.0).epsilon(1e-9));
    CHECK(b.p95AbsRelPct == Approx(10.0).epsilon(1e-9));
    CHECK(b.rmsLog == Approx(std::log(1.1)).epsilon(0.03));  // ε (1 % of the mean) damps it slightly
}

TEST_CASE("the round trip: a warped, cropped, re-exposed, white-shifted, noisy JPEG photograph, aligned by four points",
          "[compare]") {
    const HdrImage rendering = scene(160, 120);
    // The photograph's view: its pixel (x, y) sees the rendering at truth(x, y), a
    // perspective map that also crops (140 × 100 of the rendering's 160 × 120).
    const Homography truth{0.92, 0.06, 9, -0.04, 0.95, 11, 0.0003, -0.0002, 1};
    const HdrImage view = warpOnto(rendering, truth, 140, 100);
    // Exposure ×1.7, the white shifted from 3 000 K to 6 500 K, ±1 % noise, 8-bit sRGB JPEG.
    const Rgb warm = colourOfTemperature(3000), cool = colourOfTemperature(6500);
    const Rgb shift(cool.r / warm.r / (cool.g / warm.g), 1.0, cool.b / warm.b / (cool.g / warm.g));
    const double toDisplay = 1.0 / 400;
    Random rng(5, 2);
    std::vector<uint8_t> rgb8(view.pixels.size() * 3);
    REQUIRE(std::all_of(view.pixels.begin(), view.pixels.end(), [](const Rgb& p) { return std::isfinite(p.r); }));  // a crop
    for (size_t i = 0; i < view.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double v = view.pixels[i][c] * 1.7 * shift[c] * toDisplay * (1 + 0.02 * (rng.nextDouble() - 0.5));
            rgb8[3 * i + c] = static_cast<uint8_t>(std::lround(255 * quantised(v)));
        }
    const std::string jpeg = "/tmp/rayrad_test_photo.jpg";
    std::ofstream(jpeg, std::ios::binary) << encodeDisplayImage(jpeg, 140, 100, rgb8);
    const HdrImage photo = linearFromSrgb(readImage(jpeg));
    // Four points clicked on both, to a fifth of a pixel.
    std::vector<PointPair> pairs;
    for (const auto& b : std::vector<std::array<double, 2>>{{10, 8}, {131, 12}, {127, 93}, {14, 90}}) {
        const auto a = mapPoint(truth, b[0], b[1]);
        pairs.push_back({std::round(a[0] * 5) / 5, std::round(a[1] * 5) / 5, b[0], b[1]});
    }
    const HdrImage aligned = warpOnto(rendering, fitHomography(pairs), 140, 100);
    const Region whole{"image", 0, 0, 140, 100};
    const auto k = channelFactors(aligned, photo, whole);
    WARN("round trip: factors " << k[0] / toDisplay << ", " << k[1] / toDisplay << ", " << k[2] / toDisplay << " against "
                                << 1.7 * shift[0] << ", " << 1.7 * shift[1] << ", " << 1.7 * shift[2]);
    for (int c = 0; c < 3; ++c) {
        INFO("channel " << c << ": " << k[c] / toDisplay << " against " << 1.7 * shift[c]);
        CHECK(k[c] / toDisplay == Approx(1.7 * shift[c]).epsilon(0.01));
    }
    HdrImage calibrated = aligned;
    for (auto& p : calibrated.pixels)
        for (int c = 0; c < 3; ++c) p[c] *= k[c];
    for (const Region& r : {Region{"left", 5, 5, 40, 40}, Region{"red", 80, 3, 50, 25}, Region{"lower", 40, 60, 60, 35}}) {
        const ErrorFigures f = compareImages(calibrated, photo, r);
        WARN(r.name << ": mean " << f.meanRelPct << " %, median |e| " << f.medianAbsRelPct << " %, p95 " << f.p95AbsRelPct << " %");
        CHECK(std::abs(f.meanRelPct) < 2.0);
        CHECK(f.medianAbsRelPct < 2.0);
    }
}

TEST_CASE("a homography from four points is exact, from more a least-squares fit, and degenerate points are refused", "[compare]") {
    const Homography truth{1.1, 0.2, 5, -0.1, 0.9, 3, 0.001, 0.0005, 1};
    std::vector<PointPair> pairs;
    for (const auto& b : std::vector<std::array<double, 2>>{{0, 0}, {100, 0}, {100, 80}, {0, 80}, {50, 40}, {20, 70}}) {
        const auto a = mapPoint(truth, b[0], b[1]);
        pairs.push_back({a[0], a[1], b[0], b[1]});
    }
    for (size_t n : {size_t(4), size_t(6)}) {
        const Homography h = fitHomography(std::vector<PointPair>(pairs.begin(), pairs.begin() + static_cast<long>(n)));
        for (int i = 0; i < 9; ++i) CHECK(h[i] == Approx(truth[i]).margin(1e-9));
    }
    CHECK_THROWS_WITH(fitHomography(std::vector<PointPair>(pairs.begin(), pairs.begin() + 3)), Catch::Contains("at least 4 point pairs"));
    const std::vector<PointPair> line{{0, 0, 0, 0}, {1, 1, 1, 1}, {2, 2, 2, 2}, {3, 3, 3, 3}};
    CHECK_THROWS_WITH(fitHomography(line), Catch::Contains("do not determine a homography"));
}

TEST_CASE("CIEDE2000 through lcms2 matches Sharma, Wu and Dalal's published test pairs", "[compare]") {
    // Pairs 1, 7, 17 and 25 of the 34 in Sharma et al. 2005, Table 1.
    CHECK(deltaE2000({50.0000, 2.6772, -79.7751}, {50.0000, 0.0000, -82.7485}) == Approx(2.0425).margin(1e-4));
    CHECK(deltaE2000({50.0000, 0.0000, 0.0000}, {50.0000, -1.0000, 2.0000}) == Approx(2.3669).margin(1e-4));
    CHECK(deltaE2000({50.0000, 2.5000, 0.0000}, {73.0000, 25.0000, -18.0000}) == Approx(27.1492).margin(1e-4));
    CHECK(deltaE2000({60.2574, -34.0099, 36.2677}, {60.4626, -34.1751, 39.4387}) == Approx(1.2644).margin(1e-4));
    // An image against itself: 0; a colour shift shows in ΔE but not in luminance figures.
    const HdrImage a = scene(32, 24);
    HdrImage tinted = a;
    for (auto& p : tinted.pixels) p = Rgb(p.r * 1.06, p.g * 0.985, p.b * 0.9);
    const Region whole{"image", 0, 0, 32, 24};
    CHECK(compareImages(a, a, whole).meanDeltaE2000 == 0);
    CHECK(compareImages(tinted, a, whole).meanDeltaE2000 > 1.0);
}
