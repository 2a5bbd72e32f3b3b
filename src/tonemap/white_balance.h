// White balance for display: the image's white (a light's colour temperature, the mean of
// the image, or the mean of a region that should be neutral) is adapted to the display's
// D65 white by the Bradford chromatic-adaptation transform. The EXR stays as computed.
#pragma once

#include <core/hdr_image.h>

#include <array>
#include <string>

namespace rayrad::tonemap {

struct WhiteBalance {
    enum class Kind { None, Temperature, GreyWorld, Region };
    Kind kind = Kind::None;
    double kelvin = 6504;                  ///< Temperature: the illuminant's CCT
    std::array<int, 4> region{0, 0, 0, 0};  ///< Region: x, y, width, height in pixels (top-left origin)
};

/// "none", "3000K" (or "3000"), "grey-world", "region:x,y,w,h"; throws InputError naming
/// --white-balance otherwise.
WhiteBalance parseWhiteBalance(const std::string& text);

/// Throws InputError when a region white balance does not fit a width × height image
/// (checked before a render starts, and again on the image).
void checkWhiteBalance(const WhiteBalance& wb, int width, int height);

/// A 3 × 3 matrix on linear Rec.709 RGB, row-major.
using Matrix3 = std::array<std::array<double, 3>, 3>;

/// The Bradford transform from the image's white (as `wb` chooses it; linear Rec.709) to
/// D65, in linear Rec.709: M = RGB←XYZ · B⁻¹ · diag(ρσβ_D65 / ρσβ_src) · B · XYZ←RGB,
/// luminance of the white kept. Identity for None. Throws InputError for a region outside
/// the image or without light.
Matrix3 whiteBalanceMatrix(const HdrImage& image, const WhiteBalance& wb);

/// The white the image is balanced from, linear Rec.709 with luminance 1.
Rgb sourceWhite(const HdrImage& image, const WhiteBalance& wb);

Rgb applyMatrix(const Matrix3& m, const Rgb& c);

/// "3000 K → D65 (Bradford)", "grey world (source white 1.21, 0.98, 0.73) → D65 (Bradford)", "none".
std::string describe(const WhiteBalance& wb, const HdrImage& image);

}  // namespace rayrad::tonemap
