#include <app/image_output.h>

#include <app/result_checks.h>
#include <tonemap/image_io.h>

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

namespace rayrad::app {

void addImageOutputs(const std::vector<std::string>& paths, OutputFiles& files) {
    for (const auto& path : paths) {
        files.add(path);  // first: "is a directory" says more than "unknown format"
        tonemap::checkImageFormat(path);
    }
}

void stageImages(const std::vector<std::string>& paths, const HdrImage& image, const HdrImage& forDisplay,
                 const tonemap::DisplayOptions& display, const std::string& description, OutputFiles& files) {
    const bool hasLight = std::any_of(image.pixels.begin(), image.pixels.end(), [](const Rgb& p) { return p != Rgb(0.0); });
    for (const auto& path : paths) {
        if (tonemap::isHdrFormat(path)) {
            files.set(path, tonemap::encodeExr(path, image, description + "; pixel values are luminance in cd/m^2"));
        } else {
            auto rgb8 = tonemap::toDisplay(forDisplay, display);
            if (hasLight) checkDisplayImage(path, rgb8, describeExposure(display));
            const std::string how = hasLight ? tonemap::describeDisplay(forDisplay, display) : std::string();
            files.set(path, tonemap::encodeDisplayImage(path, image.width, image.height, rgb8, how.empty() ? description : description + "; " + how));
        }
    }
}

std::string snapshotPath(const std::string& path, int index) {
    std::filesystem::path p(path);
    return (p.parent_path() / fmt::format("{}.snap{:02d}{}", p.stem().string(), index, p.extension().string())).string();
}

std::string describeExposure(const tonemap::DisplayOptions& display) {
    if (display.tone.op != tonemap::ToneOperator::Exposure) return "tone operator " + tonemap::toneOperatorName(display.tone.op);
    if (!display.autoExposure) return fmt::format("{:g} stops", display.exposureStops);
    return display.exposureStops == 0 ? "auto" : fmt::format("auto {:+g} stops", display.exposureStops);
}

}  // namespace rayrad::app
