#include <tonemap/display_transform.h>

#include <core/input_error.h>

#include <OpenColorIO/OpenColorIO.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace OCIO = OCIO_NAMESPACE;

namespace rayrad::tonemap {

const char* embeddedOcioConfig() {
    // OCIO 2.1 has no built-in configs (CreateFromBuiltinConfig is 2.2+), so we ship one.
    // sRGB encoding: ExponentWithLinearTransform gamma 2.4, offset 0.055 is the exact
    // piecewise sRGB curve (0.18 → 0.4614).
    return R"(ocio_profile_version: 2

environment: {}
search_path: ""
strictparsing: true
luma: [0.2126, 0.7152, 0.0722]
description: rayrad embedded config (scene-linear Rec.709, sRGB display)

roles:
  default: Linear Rec.709
  scene_linear: Linear Rec.709
  data: Raw

displays:
  sRGB:
    - !<View> {name: Standard, colorspace: sRGB}
    - !<View> {name: Raw, colorspace: Raw}

active_displays: [sRGB]
active_views: [Standard, Raw]

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

OCIO::ConstConfigRcPtr loadConfig(const DisplayOptions& o) {
    try {
        if (!o.ocioConfig.empty()) return OCIO::Config::CreateFromFile(o.ocioConfig.c_str());
        std::istringstream in(embeddedOcioConfig());
        return OCIO::Config::CreateFromStream(in);
    } catch (const OCIO::Exception& e) {
        throw InputError(placeMessage(o.ocioConfig.empty() ? "embedded OCIO config" : o.ocioConfig, "",
                                      std::string("cannot load the OpenColorIO config: ") + e.what()));
    }
}

/// `"a", "b" or "c"`.
std::string quotedList(const std::vector<std::string>& names) {
    std::string out;
    for (size_t i = 0; i < names.size(); ++i)
        out += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + ("\"" + names[i] + "\"");
    return out.empty() ? "none" : out;
}

OCIO::ConstCPUProcessorRcPtr makeProcessor(const DisplayOptions& o) {
    auto config = loadConfig(o);
    const std::string configName = o.ocioConfig.empty() ? "embedded OCIO config" : o.ocioConfig;
    std::string display = o.display.empty() ? config->getDefaultDisplay() : o.display;
    std::vector<std::string> displays;
    for (int i = 0; i < config->getNumDisplays(); ++i) displays.push_back(config->getDisplay(i));
    if (std::find(displays.begin(), displays.end(), display) == displays.end())
        throw InputError(placeMessage(configName, "--display",
                                      "unknown display \"" + display + "\" (the config has " + quotedList(displays) + ")"));
    std::string view = o.view.empty() ? config->getDefaultView(display.c_str()) : o.view;
    std::vector<std::string> views;
    for (int i = 0; i < config->getNumViews(display.c_str()); ++i) views.push_back(config->getView(display.c_str(), i));
    if (std::find(views.begin(), views.end(), view) == views.end())
        throw InputError(placeMessage(configName, "--view",
                                      "unknown view \"" + view + "\" for display \"" + display + "\" (it has " +
                                          quotedList(views) + ")"));
    try {
        auto processor = config->getProcessor(OCIO::ROLE_SCENE_LINEAR, display.c_str(), view.c_str(),
                                              OCIO::TRANSFORM_DIR_FORWARD);
        return processor->getDefaultCPUProcessor();
    } catch (const OCIO::Exception& e) {
        throw InputError(placeMessage(o.ocioConfig.empty() ? "embedded OCIO config" : o.ocioConfig,
                                      "display \"" + display + "\", view \"" + view + "\"", e.what()));
    }
}

}  // namespace

void checkDisplayOptions(const DisplayOptions& options) { makeProcessor(options); }

DisplayOptions parseExposure(const std::string& exposure, DisplayOptions display) {
    constexpr double kMaxExposureStops = 64;
    if (exposure == "auto") return display;
    double stops = 0;
    try {
        size_t used = 0;
        stops = std::stod(exposure, &used);
        if (used != exposure.size()) throw std::invalid_argument("trailing");
    } catch (const std::exception&) {
        throw InputError(placeMessage("", "--exposure", "expected \"auto\" or a number of stops, got \"" + exposure + "\""));
    }
    if (!(std::abs(stops) <= kMaxExposureStops))
        throw InputError(placeMessage("", "--exposure", fmt::format("expected stops between -{0} and {0}, got {1}: "
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

std::vector<Rgb> toDisplayLinear(const HdrImage& image, const DisplayOptions& options) {
    const HdrImage source = balanced(image, options.whiteBalance);
    const ToneCurve curve(source, options.tone, exposureScale(source, options));
    std::vector<Rgb> out(source.pixels.size());
    for (size_t i = 0; i < out.size(); ++i) {
        const Rgb& c = source.pixels[i];
        const double world = luminance(c);
        if (!(world > 0) || !std::isfinite(world)) continue;  // black (and non-finite: refused before)
        out[i] = toDisplayGamut(c * (curve(world) / world));
    }
    return out;
}

std::string describeDisplay(const HdrImage& image, const DisplayOptions& options) {
    const HdrImage source = balanced(image, options.whiteBalance);
    const ToneCurve curve(source, options.tone, exposureScale(source, options));
    return "tone: " + curve.describe() + "; white balance: " + describe(options.whiteBalance, image);
}

std::vector<float> displayEncode(const std::vector<float>& rgb, const DisplayOptions& options) {
    auto cpu = makeProcessor(options);
    std::vector<float> out = rgb;
    for (size_t i = 0; i + 2 < out.size(); i += 3) cpu->applyRGB(&out[i]);
    return out;
}

std::vector<uint8_t> toDisplay(const HdrImage& image, const DisplayOptions& options) {
    auto cpu = makeProcessor(options);
    const std::vector<Rgb> linear = toDisplayLinear(image, options);
    std::vector<float> buf(linear.size() * 3);
    for (size_t i = 0; i < linear.size(); ++i)
        for (int c = 0; c < 3; ++c) buf[3 * i + c] = static_cast<float>(linear[i][c]);
    OCIO::PackedImageDesc desc(buf.data(), image.width, image.height, 3);
    cpu->apply(desc);
    std::vector<uint8_t> out(buf.size());
    for (size_t i = 0; i < buf.size(); ++i) {
        float v = std::isfinite(buf[i]) ? std::clamp(buf[i], 0.0f, 1.0f) : 0.0f;
        out[i] = static_cast<uint8_t>(std::lround(v * 255.0f));
    }
    return out;
}

}  // namespace rayrad::tonemap
