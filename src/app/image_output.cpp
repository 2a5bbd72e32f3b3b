#include <app/image_output.h>

#include <core/output_file.h>
#include <tonemap/image_io.h>

#include <fmt/format.h>

#include <filesystem>

namespace rayrad::app {

void checkImageOutputs(const std::vector<std::string>& paths) {
    for (const auto& path : paths) {
        tonemap::checkImageFormat(path);
        checkWritable(path);
    }
}

void writeImages(const std::vector<std::string>& paths, const HdrImage& image, const tonemap::DisplayOptions& display,
                 const std::string& description) {
    for (const auto& path : paths) {
        if (tonemap::isHdrFormat(path)) {
            tonemap::writeExr(path, image, description + "; pixel values are luminance in cd/m^2");
        } else {
            auto rgb8 = tonemap::toDisplay(image, display);
            tonemap::writeDisplayImage(path, image.width, image.height, rgb8);
        }
    }
}

std::string snapshotPath(const std::string& path, int index) {
    std::filesystem::path p(path);
    return (p.parent_path() / fmt::format("{}.snap{:02d}{}", p.stem().string(), index, p.extension().string())).string();
}

}  // namespace rayrad::app
