// rayrad compare: a rendering against a photograph or another rendering, in luminance:
// calibrated by a least-squares exposure (and optionally per-channel) factor, with
// relative errors, log-luminance RMS and SSIM over the image and named regions, a
// false-colour difference map, a side-by-side strip, and bounds for image-diff tests.
#pragma once

#include <string>
#include <vector>

namespace rayrad::app {

struct CompareOptions {
    std::string a;                       ///< the image under test (calibrated onto b)
    std::string b;                       ///< the reference
    std::string aSpace = "auto";         ///< linear | srgb | auto (EXR/HDR linear, PNG/JPEG sRGB)
    std::string bSpace = "auto";
    std::string alignFile;               ///< JSON: [{"a": [x, y], "b": [x, y]}, ...], 4 or more pairs
    std::string regionsFile;             ///< JSON: [{"name", "x", "y", "width", "height"}, ...]
    std::string calibrate = "exposure";  ///< none | exposure | channels
    std::string diffMap;                 ///< PNG/JPEG: |relative luminance difference| in %
    std::string sideBySide;              ///< PNG/JPEG: a (calibrated) | b, one exposure
    std::string report;                  ///< JSON
    std::string csv;                     ///< one row per region
    std::vector<std::string> failAbove;  ///< METRIC=VALUE
};

/// Runs the comparison; prints the figures. Returns 0, or 1 when a --fail-above bound is
/// exceeded. Throws InputError / OutputError for bad input or outputs.
int compareImages(const CompareOptions& options);

}  // namespace rayrad::app
