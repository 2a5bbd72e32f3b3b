// rayrad glare IMAGE: the glare sources, UGR and DGP of a 180° fisheye rendering, printed,
// marked on a picture and written as JSON.
#pragma once

#include <optional>
#include <string>

namespace rayrad::app {

struct GlareArgs {
    std::string image;                ///< the fisheye EXR, cd/m²
    std::optional<double> threshold;  ///< --threshold: sources above this luminance, cd/m²
    double thresholdFactor = 5;       ///< --threshold-factor: else this many times the field's mean
    std::string marked;               ///< --marked FILE.png
    std::string report;               ///< --report FILE.json
};

/// Reads the image, finds the sources, prints the figures; writes the picture and the
/// report together at the end. Returns 0.
int runGlare(const GlareArgs& args);

}  // namespace rayrad::app
