// Text on pictures set in DejaVu Sans through OpenImageIO's FreeType text rendering
// (tonemap/text_drawing.h is the caller's side).
#pragma once

#include <tonemap/text_drawing.h>

#include <cstdint>
#include <vector>

namespace rayrad::image_module {

void drawText(std::vector<uint8_t>& rgb, int width, int height, const std::vector<tonemap::TextLabel>& labels);

}  // namespace rayrad::image_module
