// Scene-linear cd/m² → display-encoded 8-bit RGB: white balance, tone reproduction
// (luminance mapped, chroma kept, gamut-mapped), then an OpenColorIO display/view.
#pragma once

#include <core/hdr_image.h>
#include <tonemap/tone_operators.h>
#include <tonemap/white_balance.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rayrad::tonemap {

/// Display options: white balance, tone reproduction, and the OCIO display transform.
struct DisplayOptions {
    WhiteBalance whiteBalance;  ///< applied first, on linear Rec.709
    ToneOptions tone;           ///< the operator and its parameters
    bool autoExposure = true;   ///< exposure operator: log-average luminance → 0.18
    double exposureStops = 0;   ///< with autoExposure: added to it; else absolute, 2^stops per cd/m²
    std::string ocioConfig;     ///< path to a user .ocio file; empty = rayrad's embedded config
    std::string display;        ///< empty = the config's default display
    std::string view;           ///< empty = the display's default view
};

/// --exposure: "auto" (the options unchanged) or a finite number of stops within ±64
/// (2^64 ≈ 1.8e19 per cd/m²), which makes the exposure absolute. Throws InputError.
DisplayOptions parseExposure(const std::string& exposure, DisplayOptions display);

/// Throws InputError for a config that does not load, or a display or view it does not
/// have (the message lists the ones it has). Call it before long work. Returns a warning
/// when a tone operator other than exposure feeds a view with its own tone curve.
std::optional<std::string> checkDisplayOptions(const DisplayOptions& options);

/// The name of the view's OCIO view transform ("ACES 1.0 SDR-video"), or "" for a view
/// that only encodes. A view transform brings its own tone curve and gamut mapping, so
/// such a view receives the tone-mapped values scene-referred (not brought into [0, 1]).
std::string viewToneCurve(const DisplayOptions& options);

/// The multiplier applied to cd/m² before the display transform.
double exposureScale(const HdrImage& image, const DisplayOptions& options);

/// rayrad's own small OCIO config (scene-linear Rec.709; display sRGB with the views
/// "Standard" (the piecewise sRGB curve), "ACES 1.0 SDR-video" (OCIO's built-in ACES 1.0
/// output transform) and "Raw"), so nothing depends on $OCIO.
const char* embeddedOcioConfig();

/// Converts to 8-bit display RGB, row-major, 3 bytes a pixel: the white balance, then each
/// pixel's RGB scaled by L_d / L_w (the tone operator's display luminance over the
/// world luminance) and brought into the display gamut toward grey (toDisplayGamut),
/// then OCIO's processor from the scene-linear role to (display, view), then quantised.
/// The view receives display-relative linear values in [0, 1] (a view with its own tone
/// curve: the tone-mapped values without the gamut step). Throws InputError for a
/// bad config path or unknown display/view (with the names), or a bad white-balance region.
std::vector<uint8_t> toDisplay(const HdrImage& image, const DisplayOptions& options);

/// The display linear RGB before the OCIO view (white balanced, tone mapped, in gamut),
/// for tests and comparisons.
std::vector<Rgb> toDisplayLinear(const HdrImage& image, const DisplayOptions& options);

/// "tone: ward: L_wa 54.2 cd/m², L_dmax 100 cd/m²; white balance: 3000 K → D65 (Bradford)",
/// as written into the display image's metadata.
std::string describeDisplay(const HdrImage& image, const DisplayOptions& options);

/// Applies the display transform to one scene-linear value (for tests).
std::vector<float> displayEncode(const std::vector<float>& rgb, const DisplayOptions& options);

}  // namespace rayrad::tonemap
