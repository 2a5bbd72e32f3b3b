#include <tonemap/text_drawing.h>

#include <tonemap/image_library.h>

namespace rayrad::tonemap {

void drawText(std::vector<uint8_t>& rgb, int width, int height, const std::vector<TextLabel>& labels) {
    if (labels.empty()) return;
    imageLibrary().drawText(rgb, width, height, labels);
}

}  // namespace rayrad::tonemap
