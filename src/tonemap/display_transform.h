// Scene-linear cd/m² → display-encoded 8-bit RGB, through an OpenColorIO display/view.
#pragma once

#include <core/hdr_image.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace rayrad::tonemap {

/// Display options: exposure and the OCIO display transform.
struct DisplayOptions {
    bool autoExposure = true;   ///< key-value exposure: log-average luminance → 0.18
    double exposureStops = 0;   ///< with autoExposure: added to it; else absolute, 2^stops per cd/m²
    std::string ocioConfig;     ///< path to a user .ocio file; empty = rayrad's embedded config
    std::string display;        ///< empty = the config's default display
    std::string view;           ///< empty = the display's default view
};

/// Throws InputError for a config that does not load, or a display or view it does not
/// have (the message lists the ones it has). Call it before long work.
void checkDisplayOptions(const DisplayOptions& options);

/// The multiplier applied to cd/m² before the display transform.
double exposureScale(const HdrImage& image, const DisplayOptions& options);

/// rayrad's own small OCIO config (scene-linear Rec.709; display sRGB with the
/// piecewise sRGB curve, view "Standard"; view "Raw"), so nothing depends on $OCIO.
const char* embeddedOcioConfig();

/// Converts to 8-bit display RGB, row-major, 3 bytes a pixel. Luminance is scaled by
/// the exposure, then OCIO's processor from the scene-linear role to (display, view)
/// is applied, then values are clamped and quantised. Throws InputError for a bad
/// config path or unknown display/view (with the names).
std::vector<uint8_t> toDisplay(const HdrImage& image, const DisplayOptions& options);

/// Applies the display transform to one scene-linear value (for tests).
std::vector<float> displayEncode(const std::vector<float>& rgb, const DisplayOptions& options);

}  // namespace rayrad::tonemap
