#include <tonemap/display_transform.h>

#include <core/input_error.h>
#include <tonemap/image_library.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

namespace rayrad::tonemap {

const char* embeddedOcioConfig() {
    // OCIO 2.1 has no built-in configs (CreateFromBuiltinConfig is 2.2+), so we ship one.
    // sRGB encoding: ExponentWithLinearTransform gamma 2.4, offset 0.055 is the exact
    // piecewise sRGB curve (0.18 → 0.4614).
    // The ACES view is assembled from OCIO 2.1's built-in transforms (the Academy's CTL
    // implemented in the library, no LUT files): linear Rec.709 → ACEScg (the inverse of
    // AP1 → Rec.709, Bradford D60 ↔ D65) → ACES2065-1 → the ACES 1.0 reference rendering
    // and SDR video output transform (100 cd/m², dim surround) to CIE XYZ D65 → the
    // piecewise sRGB display. It has its own tone curve: it receives scene-referred values.
    return R"(ocio_profile_version: 2

environment: {}
search_path: ""
strictparsing: true
luma: [0.2126, 0.7152, 0.0722]
description: rayrad embedded config (scene-linear Rec.709, sRGB display; views Standard, ACES 1.0 SDR-video, Raw)

roles:
  default: Linear Rec.709
  scene_linear: Linear Rec.709
  data: Raw

file_rules:
  - !<Rule> {name: Default, colorspace: default}

displays:
  sRGB:
    - !<View> {name: Standard, colorspace: sRGB}
    - !<View> {name: ACES 1.0 SDR-video, view_transform: ACES 1.0 SDR-video, display_colorspace: sRGB display}
    - !<View> {name: Raw, colorspace: Raw}

active_displays: [sRGB]
active_views: [Standard, ACES 1.0 SDR-video, Raw]

view_transforms:
  - !<ViewTransform>
    name: ACES 1.0 SDR-video
    description: ACES 1.0 reference rendering + SDR video output transform (100 cd/m2, D65, dim surround)
    from_scene_reference: !<GroupTransform>
      children:
        - !<BuiltinTransform> {style: "UTILITY - ACES-AP1_to_LINEAR-REC709_BFD", direction: inverse}
        - !<BuiltinTransform> {style: "ACEScg_to_ACES2065-1"}
        - !<BuiltinTransform> {style: "ACES-OUTPUT - ACES2065-1_to_CIE-XYZ-D65 - SDR-VIDEO_1.0"}

display_colorspaces:
  - !<ColorSpace>
    name: sRGB display
    family: Display
    encoding: sdr-video
    description: sRGB display encoding from CIE XYZ (D65), for views with a view transform
    isdata: false
    from_display_reference: !<BuiltinTransform> {style: "DISPLAY - CIE-XYZ-D65_to_sRGB"}

colorspaces:
  - !<ColorSpace>
    name: Linear Rec.709
    family: Linear
    encoding: scene-linear
    bitdepth: 32f
    description: Scene-linear Rec.709 primaries, D65 white
    isdata: false

  - !<ColorSpace>
    name: sRGB
    family: Display
    encoding: sdr-video
    bitdepth: 8ui
    description: sRGB display encoding (IEC 61966-2-1 piecewise curve)
    isdata: false
    from_scene_reference: !<ExponentWithLinearTransform> {gamma: 2.4, offset: 0.055, direction: inverse}

  - !<ColorSpace>
    name: Raw
    family: Utility
    bitdepth: 32f
    isdata: true
)";
}

namespace {

/// The options' display and view, resolved in their config (the embedded one by default).
ResolvedView resolveDisplayView(const DisplayOptions& o) {
    return imageLibrary().resolveView(o.ocioConfig, o.ocioConfig.empty() ? embeddedOcioConfig() : "", o.display,
                                      o.view);
}

}  // namespace

std::optional<std::string> checkDisplayOptions(const DisplayOptions& options) {
    const std::string curve = resolveDisplayView(options).viewTransform;
    if (curve.empty() || options.tone.op == ToneOperator::Exposure) return std::nullopt;
    return "--view: the view's transform \"" + curve + "\" has its own tone curve, and --tonemap " +
           toneOperatorName(options.tone.op) +
           " maps the luminance before it: two tone curves (use --tonemap exposure)";
}

std::string viewToneCurve(const DisplayOptions& options) {
    return resolveDisplayView(options).viewTransform;
}

DisplayOptions parseExposure(const std::string& exposure, DisplayOptions display) {
    constexpr double kMaxExposureStops = 64;
    if (exposure == "auto") return display;
    double stops = 0;
    try {
        size_t used = 0;
        stops = std::stod(exposure, &used);
        if (used != exposure.size()) throw std::invalid_argument("trailing");
    } catch (const std::exception&) {
        throw InputError(
            placeMessage("", "--exposure", "expected \"auto\" or a number of stops, got \"" + exposure + "\""));
    }
    if (!(std::abs(stops) <= kMaxExposureStops))
        throw InputError(placeMessage("", "--exposure",
                                      fmt::format("expected stops between -{0} and {0}, got {1}: "
                                                  "that would make every pixel black or white",
                                                  kMaxExposureStops, exposure)));
    display.exposureStops = stops;
    display.autoExposure = false;
    return display;
}

double exposureScale(const HdrImage& image, const DisplayOptions& o) {
    double stops = std::pow(2.0, o.exposureStops);
    if (!o.autoExposure) return stops;
    // Reinhard's key value: the log-average luminance of lit pixels maps to 0.18.
    const double average = logAverageLuminance(image);
    return average > 0 ? 0.18 / average * stops : stops;
}

namespace {

HdrImage balanced(const HdrImage& image, const WhiteBalance& wb) {
    if (wb.kind == WhiteBalance::Kind::None) return image;
    const Matrix3 m = whiteBalanceMatrix(image, wb);
    HdrImage out = image;
    for (auto& p : out.pixels) p = applyMatrix(m, p);
    return out;
}

}  // namespace

namespace {

/// White balanced, each pixel scaled by L_d / L_w; brought into the display gamut unless
/// the values go on to a view with its own tone curve (which expects scene-referred
/// values above 1 and maps them itself).
std::vector<Rgb> toneMapped(const HdrImage& image, const DisplayOptions& options, bool intoDisplayGamut) {
    const HdrImage source = balanced(image, options.whiteBalance);
    const ToneCurve curve(source, options.tone, exposureScale(source, options));
    std::vector<Rgb> out(source.pixels.size());
    for (size_t i = 0; i < out.size(); ++i) {
        const Rgb& c = source.pixels[i];
        const double world = luminance(c);
        if (!(world > 0) || !std::isfinite(world)) continue;  // black (and non-finite: refused before)
        const Rgb mapped = c * (curve(world) / world);
        out[i] = intoDisplayGamut ? toDisplayGamut(mapped) : mapped;
    }
    return out;
}

}  // namespace

std::vector<Rgb> toDisplayLinear(const HdrImage& image, const DisplayOptions& options) {
    return toneMapped(image, options, true);
}

std::string describeDisplay(const HdrImage& image, const DisplayOptions& options) {
    const HdrImage source = balanced(image, options.whiteBalance);
    const ToneCurve curve(source, options.tone, exposureScale(source, options));
    const std::string viewCurve = viewToneCurve(options);
    return "tone: " + curve.describe() + "; white balance: " + describe(options.whiteBalance, image) +
           (viewCurve.empty() ? "" : "; view transform: " + viewCurve);
}

std::vector<float> displayEncode(const std::vector<float>& rgb, const DisplayOptions& options) {
    const ResolvedView view = resolveDisplayView(options);
    std::vector<float> out = rgb;
    view.processor->apply(out.data(), out.size() / 3);
    return out;
}

std::vector<uint8_t> toDisplay(const HdrImage& image, const DisplayOptions& options) {
    const ResolvedView view = resolveDisplayView(options);
    const std::vector<Rgb> linear = toneMapped(image, options, view.viewTransform.empty());
    std::vector<float> buf(linear.size() * 3);
    for (size_t i = 0; i < linear.size(); ++i)
        for (int c = 0; c < 3; ++c) buf[3 * i + c] = static_cast<float>(linear[i][c]);
    view.processor->apply(buf.data(), linear.size());
    std::vector<uint8_t> out(buf.size());
    for (size_t i = 0; i < buf.size(); ++i) {
        float v = std::isfinite(buf[i]) ? std::clamp(buf[i], 0.0f, 1.0f) : 0.0f;
        out[i] = static_cast<uint8_t>(std::lround(v * 255.0f));
    }
    return out;
}

}  // namespace rayrad::tonemap
