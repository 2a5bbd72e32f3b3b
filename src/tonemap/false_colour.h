// False colour: a field of values (illuminance on a grid, luminance of a rendering) shown
// as colours on a scale, with isolines at the scale's levels and a legend with numbers
// and units, text set in a real font (DejaVu Sans through OpenImageIO and FreeType).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace rayrad::tonemap {

/// Values on a width × height raster, row-major from the top; NaN where there is none.
struct ScalarField {
    int width = 0, height = 0;
    std::vector<double> values;
};

struct FalseColourOptions {
    bool logScale = false;   ///< else linear from 0
    double maximum = 0;      ///< top of the scale; 0: the field's maximum (linear: rounded up to a level)
    double decades = 3;      ///< log scale: the bottom is maximum / 10^decades
    int pixelsPerValue = 1;  ///< each value drawn as an n × n block (grids), interpolated bilinearly
    bool isolines = true;    ///< lines where the value crosses a level
    std::string title;       ///< above the legend
    std::string unit;        ///< after the numbers ("lx", "cd/m²")
};

/// An 8-bit RGB picture, row-major, 3 bytes a pixel.
struct Picture {
    int width = 0, height = 0;
    std::vector<uint8_t> rgb;
};

/// The levels of the scale (the legend's ticks and the isolines) for values from
/// `minimum` to `maximum` (> 0): linear steps of 1, 2, 2.5 or 5 × 10^k, at most 8 of them
/// from 0 (from a level below the minimum when it is above a quarter of the maximum),
/// the last at or above the maximum; log 1, 2, 5 × 10^k over `decades` below the maximum.
std::vector<double> scaleLevels(double minimum, double maximum, const FalseColourOptions& options);

/// The colour (linear in [0, 1]) of position t ∈ [0, 1] on the scale: dark blue through
/// cyan, green and yellow to red (a perceptually ordered palette after Google's Turbo).
void paletteColour(double t, float rgb[3]);

/// The field in false colour with the legend at its right. Throws InputError when the
/// font cannot be found (package fonts-dejavu-core).
Picture renderFalseColour(const ScalarField& field, const FalseColourOptions& options);

/// Stacks pictures top to bottom on a white ground (several grids in one file).
Picture stackPictures(const std::vector<Picture>& pictures);

}  // namespace rayrad::tonemap
