// ꟻLIP (tonemap/image_flip) at the cases its definition fixes: identical images 0; flat
// fields, where the feature term vanishes and the colour term is the redistributed HyAB
// distance (pure green against pure blue is the largest: 1); an isolated bright pixel (a
// firefly) stands out through the point detector; more noise, more error.
#include <tonemap/image_flip.h>

#include "test_support.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace rayrad;

namespace {

std::vector<Rgb> flat(int w, int h, Rgb c) { return std::vector<Rgb>(static_cast<size_t>(w) * h, c); }

double mean(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return s / static_cast<double>(v.size());
}

}  // namespace

TEST_CASE("FLIP: identical images 0, flat fields their colour term, green against blue 1", "[flip]") {
    const int w = 48, h = 32;
    const auto grey = flat(w, h, Rgb(0.3));
    for (double e : tonemap::flipErrorMap(grey, grey, w, h)) CHECK(e == Approx(0).margin(1e-12));

    // Green against blue is c_max, mapped to 1 (everywhere: the fields are flat).
    const auto green = tonemap::flipErrorMap(flat(w, h, Rgb(0, 1, 0)), flat(w, h, Rgb(0, 0, 1)), w, h);
    for (double e : green) CHECK(e == Approx(1).margin(1e-9));

    // Black against white: HyAB = 100 (L* from 0 to 100, a* = b* = 0), so the colour term
    // is p_t + (100^q_c − p_c c_max) / (c_max − p_c c_max) (1 − p_t) when 100^q_c ≥ p_c c_max,
    // with c_max the green–blue HyAB^q_c computed independently here (CIELAB of sRGB primaries,
    // Hunt: a, b × 0.01 L).
    auto lab = [](double X, double Y, double Z) {  // relative to D65
        auto f = [](double t) { return t > std::pow(6.0 / 29, 3) ? std::cbrt(t) : t / (3 * std::pow(6.0 / 29, 2)) + 4.0 / 29; };
        const double L = 116 * f(Y) - 16;
        return std::array<double, 3>{L, 0.01 * L * 500 * (f(X) - f(Y)), 0.01 * L * 200 * (f(Y) - f(Z))};
    };
    const auto g = lab(0.3575761 / 0.95047, 0.7151522, 0.1191920 / 1.08883);
    const auto b = lab(0.1804375 / 0.95047, 0.0721750, 0.9503041 / 1.08883);
    const double cmax = std::pow(std::abs(g[0] - b[0]) + std::hypot(g[1] - b[1], g[2] - b[2]), 0.7);
    const double e = std::pow(100.0, 0.7);
    const double expected = e < 0.4 * cmax ? 0.95 / (0.4 * cmax) * e : 0.95 + (e - 0.4 * cmax) / (cmax - 0.4 * cmax) * 0.05;
    INFO("c_max " << cmax << ", expected " << expected);
    const auto bw = tonemap::flipErrorMap(flat(w, h, Rgb(0.0)), flat(w, h, Rgb(1.0)), w, h);
    CHECK(bw[static_cast<size_t>(h / 2) * w + w / 2] == Approx(expected).epsilon(1e-6));
}

TEST_CASE("FLIP: a firefly stands out, and more noise means more error", "[flip]") {
    const int w = 64, h = 64;
    const auto reference = flat(w, h, Rgb(0.2));
    auto firefly = reference;
    firefly[static_cast<size_t>(32) * w + 32] = Rgb(1.0);
    const auto map = tonemap::flipErrorMap(reference, firefly, w, h);
    // At the firefly about 0.39 (its colour is blurred by the eye's contrast sensitivity, a
    // pixel being 1/67°; the point detector raises it); nothing far from it.
    CHECK(map[static_cast<size_t>(32) * w + 32] > 0.2);
    CHECK(map[static_cast<size_t>(5) * w + 5] < 1e-9);
    auto noisy = [&](double amplitude) {
        std::vector<Rgb> out = reference;
        uint32_t state = 12345;
        for (auto& p : out) {
            state = state * 1664525u + 1013904223u;
            p = Rgb(0.2 + amplitude * ((state >> 8) / double(1 << 24) - 0.5));
        }
        return out;
    };
    const double weak = mean(tonemap::flipErrorMap(reference, noisy(0.02), w, h));
    const double strong = mean(tonemap::flipErrorMap(reference, noisy(0.2), w, h));
    INFO("mean FLIP: noise ±1 % " << weak << ", ±10 % " << strong);
    CHECK(weak > 0);
    CHECK(strong > 2 * weak);
    CHECK(strong < 1);
}
