#include <image_module/display_views.h>

#include <core/input_error.h>

#include <OpenColorIO/OpenColorIO.h>

#include <algorithm>
#include <sstream>

namespace OCIO = OCIO_NAMESPACE;

namespace rayrad::image_module {

namespace {

OCIO::ConstConfigRcPtr loadConfig(const std::string& configFile, const std::string& embeddedConfig) {
    try {
        if (!configFile.empty()) return OCIO::Config::CreateFromFile(configFile.c_str());
        std::istringstream in(embeddedConfig);
        return OCIO::Config::CreateFromStream(in);
    } catch (const OCIO::Exception& e) {
        throw InputError(placeMessage(configFile.empty() ? "embedded OCIO config" : configFile, "",
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

/// A display and view of a loaded config, both checked to exist.
struct DisplayView {
    OCIO::ConstConfigRcPtr config;
    std::string configName, display, view;
};

DisplayView resolveDisplayView(const std::string& configFile, const std::string& embeddedConfig,
                               const std::string& display, const std::string& view) {
    DisplayView dv;
    dv.config = loadConfig(configFile, embeddedConfig);
    const auto& config = dv.config;
    dv.configName = configFile.empty() ? "embedded OCIO config" : configFile;
    dv.display = display.empty() ? config->getDefaultDisplay() : display;
    std::vector<std::string> displays;
    for (int i = 0; i < config->getNumDisplays(); ++i) displays.push_back(config->getDisplay(i));
    if (std::find(displays.begin(), displays.end(), dv.display) == displays.end())
        throw InputError(
            placeMessage(dv.configName, "--display",
                         "unknown display \"" + dv.display + "\" (the config has " + quotedList(displays) + ")"));
    dv.view = view.empty() ? config->getDefaultView(dv.display.c_str()) : view;
    std::vector<std::string> views;
    for (int i = 0; i < config->getNumViews(dv.display.c_str()); ++i)
        views.push_back(config->getView(dv.display.c_str(), i));
    if (std::find(views.begin(), views.end(), dv.view) == views.end())
        throw InputError(placeMessage(
            dv.configName, "--view",
            "unknown view \"" + dv.view + "\" for display \"" + dv.display + "\" (it has " + quotedList(views) + ")"));
    return dv;
}

/// The view transform's name ("" for a view that only encodes).
std::string viewTransformOf(const DisplayView& dv) {
    const char* name = dv.config->getDisplayViewTransformName(dv.display.c_str(), dv.view.c_str());
    return name ? name : "";
}

OCIO::ConstCPUProcessorRcPtr makeProcessor(const DisplayView& dv) {
    try {
        auto processor = dv.config->getProcessor(OCIO::ROLE_SCENE_LINEAR, dv.display.c_str(), dv.view.c_str(),
                                                 OCIO::TRANSFORM_DIR_FORWARD);
        return processor->getDefaultCPUProcessor();
    } catch (const OCIO::Exception& e) {
        throw InputError(
            placeMessage(dv.configName, "display \"" + dv.display + "\", view \"" + dv.view + "\"", e.what()));
    }
}

/// An OCIO CPU processor applied to packed RGB floats.
class OcioProcessor final : public tonemap::DisplayProcessor {
  public:
    explicit OcioProcessor(OCIO::ConstCPUProcessorRcPtr cpu) : m_cpu(std::move(cpu)) {}
    void apply(float* rgb, size_t pixels) const override {
        if (pixels == 0) return;
        // One row of `pixels`: OCIO's packed image needs no particular shape.
        OCIO::PackedImageDesc desc(rgb, static_cast<long>(pixels), 1, 3);
        m_cpu->apply(desc);
    }

  private:
    OCIO::ConstCPUProcessorRcPtr m_cpu;
};

}  // namespace

tonemap::ResolvedView resolveView(const std::string& configFile, const std::string& embeddedConfig,
                                  const std::string& display, const std::string& view) {
    const DisplayView dv = resolveDisplayView(configFile, embeddedConfig, display, view);
    return {viewTransformOf(dv), std::make_shared<OcioProcessor>(makeProcessor(dv))};
}

}  // namespace rayrad::image_module
