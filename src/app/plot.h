// A minimal line plot written as PNG (for validate's error-against-time figures).
#pragma once

#include <core/math.h>

#include <string>
#include <vector>

namespace rayrad::app {

struct PlotSeries {
    std::string label;
    Rgb color{0.0};             ///< 0..1 display RGB
    std::vector<Vec2> points;   ///< (x, y) in data units
};

struct PlotPanel {
    std::string title;
    std::string xLabel, yLabel;
    bool logX = true;
    double yMin = -10, yMax = 10;  ///< values outside are clipped to the frame
    std::vector<PlotSeries> series;
};

/// Draws the panels side by side with axes, ticks, a zero line and a legend, and
/// writes a PNG (atomically). Text is set in DejaVu Sans (tonemap/text_drawing.h).
void writePlotPng(const std::string& path, const std::vector<PlotPanel>& panels);

}  // namespace rayrad::app
