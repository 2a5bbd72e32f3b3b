// Tiles of one rendering, for spreading a big image over processes or machines: render
// --tile i/n writes the i-th of n horizontal bands (the same pixels as the whole image:
// each pixel has its own random stream), rayrad merge joins them into the full EXR,
// bit-identical to a single render.
#pragma once

#include <app/pipeline.h>
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

/// What makes two renders' pixels the same, as 16 hex digits (64-bit FNV-1a): the
/// solution's fingerprint (geometry, materials, lights, radiosity settings), the camera and
/// the render settings. Tiles of one image carry the same; merge refuses others.
std::string renderFingerprint(const PipelineRun& run);

/// The tile's EXR: its rows of `image` (cd/m²), with what merge needs to place it and to
/// write the whole image as render would (`description`, the full image's description;
/// `fingerprint`, renderFingerprint of the run).
std::string encodeTile(const std::string& path, const HdrImage& image, const Tile& t, const std::string& description,
                       const std::string& fingerprint);

/// rayrad merge OUT... TILE...: checks the tiles form one image (same width, height, tile
/// count, description and render fingerprint; every index once), joins them, checks the result and writes
/// each output (.exr as render writes it, .png/.jpg through the default display transform).
/// Returns the exit code. Throws InputError / OutputError / ResultError.
int mergeTiles(const std::vector<std::string>& outputs, const std::vector<std::string>& tiles);

}  // namespace rayrad::app
