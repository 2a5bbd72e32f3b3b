// The false-colour pictures a designer hands over: each sensor grid's illuminance (with its
// statistics in the title), and a rendering's luminance.
#pragma once

#include <app/sensor_table.h>
#include <core/hdr_image.h>
#include <tonemap/false_colour.h>

#include <vector>

namespace rayrad::app {

/// Every grid of the results as a plan in false colour (linear lx, isolux lines, legend),
/// stacked top to bottom; cells outside a work plane's outline grey. Empty when no grid.
tonemap::Picture gridPicture(const std::vector<SensorResult>& results);

/// A rendering's luminance in false colour: log scale over three decades below the
/// brightest pixel (cd/m²), isolines at 1, 2, 5 × 10^k.
tonemap::Picture luminancePicture(const HdrImage& image);

}  // namespace rayrad::app
