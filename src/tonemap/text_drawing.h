// Text on pictures (legends, plot labels), set in DejaVu Sans through OpenImageIO's
// FreeType text rendering (Debian fonts-dejavu-core).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace rayrad::tonemap {

struct TextLabel {
    enum class Align { Left, Centre, Right };
    int x = 0, y = 0;            ///< px: the anchor
    std::string text;
    Align align = Align::Left;   ///< where x is on the text
    bool middle = false;         ///< y is the text's vertical middle, else its baseline
    int size = 15;               ///< px
};

/// Draws the labels in dark ink into an 8-bit RGB picture (row-major, 3 bytes a pixel).
/// Throws InputError when the font cannot be found.
void drawText(std::vector<uint8_t>& rgb, int width, int height, const std::vector<TextLabel>& labels);

}  // namespace rayrad::tonemap
