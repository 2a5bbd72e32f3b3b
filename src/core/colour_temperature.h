// The colour of a light given as a correlated colour temperature (lights, white balance).
#pragma once

#include <core/math.h>

namespace rayrad {

constexpr double kMinColourTemperature = 1667;   ///< K, the range of the Planckian-locus fit
constexpr double kMaxColourTemperature = 25000;  ///< K

/// Linear Rec.709 RGB of a black body at `kelvin` (1667–25 000 K), luminance 1: the
/// chromaticity of the Planckian locus (Kim et al. 2002 cubic fit, within 1e-3 in xy of
/// Planck's law), to XYZ with Y = 1, to linear sRGB (D65 white, no chromatic
/// adaptation: 6504 K is near white, 2700 K orange). Negative components clipped.
Rgb colourOfTemperature(double kelvin);

}  // namespace rayrad
