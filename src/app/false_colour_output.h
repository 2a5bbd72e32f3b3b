// The false-colour pictures a designer hands over: each sensor grid's illuminance (with its
// statistics in the title), and a rendering's luminance.
#pragma once

#include <app/grid_statistics.h>
#include <app/sensor_table.h>
#include <core/hdr_image.h>
#include <tonemap/false_colour.h>

#include <optional>
#include <vector>

namespace rayrad::app {

/// Every grid of the results as a plan in false colour (linear lx, isolux lines, legend),
/// stacked top to bottom; cells outside a work plane's outline grey. Empty when no grid.
/// Under a sky without sun the plan shows the daylight factor (%) and its statistics, with
/// EN 17037's method 1 shares when `medianExternalIlluminance` (lx) is given.
tonemap::Picture gridPicture(const std::vector<SensorResult>& results,
                             std::optional<double> medianExternalIlluminance = std::nullopt);

/// A grid plan's title: its illuminance statistics, or under a sky without sun its daylight
/// factors, with a second line for EN 17037's method 1 when the site's median is known.
std::string gridPlanTitle(const GridStatistics& s);

/// A rendering's luminance in false colour: log scale over three decades below the
/// brightest pixel (cd/m²), isolines at 1, 2, 5 × 10^k.
tonemap::Picture luminancePicture(const HdrImage& image);

}  // namespace rayrad::app
