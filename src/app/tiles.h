// Tiles of one rendering, for spreading a big image over processes or machines: render
// --tile i/n writes the i-th of n horizontal bands (the same pixels as the whole image:
// each pixel has its own random stream), rayrad merge joins them into the full EXR,
// bit-identical to a single render.
#pragma once

#include <core/hdr_image.h>

#include <string>
#include <utility>
#include <vector>

namespace rayrad::app {

struct Tile {
    int index = 0;  ///< 1 … count
    int count = 0;  ///< 0: the whole image
};

/// "2/4" → {2, 4}. Throws InputError naming --tile otherwise.
Tile parseTile(const std::string& text);

/// The rows [first, last) tile `t` covers in an image `height` rows high.
std::pair<int, int> tileRows(const Tile& t, int height);

/// The tile's EXR: its rows of `image` (cd/m²), with what merge needs to place it and to
/// write the whole image as render would (`description`, the full image's description).
std::string encodeTile(const std::string& path, const HdrImage& image, const Tile& t, const std::string& description);

/// rayrad merge OUT... TILE...: checks the tiles form one image (same width, height, tile
/// count and description; every index once), joins them, checks the result and writes
/// each output (.exr as render writes it, .png/.jpg through the default display transform).
/// Returns the exit code. Throws InputError / OutputError / ResultError.
int mergeTiles(const std::vector<std::string>& outputs, const std::vector<std::string>& tiles);

}  // namespace rayrad::app
