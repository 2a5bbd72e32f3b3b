// Aligning a rendering with a photograph: a homography from four or more corresponding
// points, and the rendering resampled onto the photograph's pixel grid.
#pragma once

#include <core/hdr_image.h>

#include <array>
#include <vector>

namespace rayrad::tonemap {

/// A point in image a and the same point in image b, in pixels from the top-left corner
/// (pixel i covers [i, i + 1); its centre is i + 0.5).
struct PointPair {
    double ax, ay, bx, by;
};

/// The projective map from b's pixels to a's, row-major with h[8] = 1:
/// (x_a, y_a) = ((h0 x + h1 y + h2) / w, (h3 x + h4 y + h5) / w), w = h6 x + h7 y + 1.
using Homography = std::array<double, 9>;

/// The homography through the pairs: exact for four, least squares (direct linear
/// transform, coordinates normalised) for more. Throws InputError for fewer than four
/// pairs or points in a degenerate layout (three on a line).
Homography fitHomography(const std::vector<PointPair>& pairs);

/// Where b's pixel position (x, y) falls in a.
std::array<double, 2> mapPoint(const Homography& bToA, double x, double y);

/// a resampled onto a width × height grid (b's): each pixel centre mapped into a and read
/// bilinearly; NaN where it falls outside a (those pixels are left out of every figure).
HdrImage warpOnto(const HdrImage& a, const Homography& bToA, int width, int height);

}  // namespace rayrad::tonemap
