// A linear RGB image in absolute units (cd/m²), the ray tracer's output.
#pragma once

#include <core/math.h>

#include <vector>

namespace rayrad {

/// Linear Rec.709 RGB, luminance in cd/m², row-major from the top-left pixel.
struct HdrImage {
    int width = 0;
    int height = 0;
    std::vector<Rgb> pixels;

    HdrImage() = default;
    HdrImage(int w, int h) : width(w), height(h), pixels(static_cast<size_t>(w) * h, Rgb(0.0)) {}
    Rgb& at(int x, int y) { return pixels[static_cast<size_t>(y) * width + x]; }
    const Rgb& at(int x, int y) const { return pixels[static_cast<size_t>(y) * width + x]; }
};

}  // namespace rayrad
