// rayrad compare's figures (issue 15): the exposure and per-channel factors recovered from
// a fake photograph, relative errors, log RMS and SSIM.
#include <core/random.h>
#include <tonemap/image_metrics.h>

#include "test_support.h"

#include <catch2/catch.hpp>

#include <cmath>

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
