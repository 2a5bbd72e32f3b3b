#include <image_module/text_drawing.h>

#include <core/input_error.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace rayrad::image_module {

namespace {
constexpr const char* kFont = "DejaVuSans";
}

void drawText(std::vector<uint8_t>& rgb, int width, int height, const std::vector<tonemap::TextLabel>& labels) {
    if (labels.empty()) return;
    OIIO::ImageBuf buf(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::UINT8), rgb.data());
    OIIO::ImageBuf work(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT));
    OIIO::ImageBufAlgo::copy(work, buf);
    const float ink[3] = {0.05f, 0.05f, 0.05f};
    using OIIO::ImageBufAlgo::TextAlignX;
    using OIIO::ImageBufAlgo::TextAlignY;
    for (const auto& l : labels) {
        const TextAlignX ax = l.align == tonemap::TextLabel::Align::Left     ? TextAlignX::Left
                              : l.align == tonemap::TextLabel::Align::Centre ? TextAlignX::Center
                                                                             : TextAlignX::Right;
        if (!OIIO::ImageBufAlgo::render_text(work, l.x, l.y, l.text, l.size, kFont, ink, ax,
                                             l.middle ? TextAlignY::Center : TextAlignY::Baseline))
            throw InputError(
                fmt::format("cannot draw text: {} (is the font {} installed? Debian package fonts-dejavu-core)",
                            work.geterror(), kFont));
    }
    std::vector<float> pixels(rgb.size());
    work.get_pixels(OIIO::ROI(0, width, 0, height, 0, 1, 0, 3), OIIO::TypeDesc::FLOAT, pixels.data());
    for (size_t i = 0; i < pixels.size(); ++i)
        rgb[i] = static_cast<uint8_t>(std::lround(std::clamp(pixels[i], 0.0f, 1.0f) * 255));
}

}  // namespace rayrad::image_module
