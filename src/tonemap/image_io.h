// Image files through OpenImageIO: EXR (linear cd/m²) and 8-bit PNG/JPEG, written atomically.
#pragma once

#include <core/hdr_image.h>

#include <cstdint>
#include <string>
#include <vector>

namespace rayrad::tonemap {

/// True for the extensions we write as linear floats (.exr); PNG/JPEG are display images.
bool isHdrFormat(const std::string& path);
/// Throws InputError unless the extension is one we can write (.exr .png .jpg .jpeg).
void checkImageFormat(const std::string& path);

/// Writes linear Rec.709 in absolute luminance (cd/m²), 32-bit floats (half floats overflow at 65504 cd/m²), with metadata
/// saying so, and no time stamp (the same input gives the same bytes). Temp file +
/// rename: never leaves a partial file.
void writeExr(const std::string& path, const HdrImage& image, const std::string& description);

/// Writes display-encoded 8-bit RGB (already tone mapped and encoded).
void writeDisplayImage(const std::string& path, int width, int height, const std::vector<uint8_t>& rgb8);

/// Reads any image OIIO can read as linear floats as stored (tests, image diffs).
HdrImage readImage(const std::string& path);

}  // namespace rayrad::tonemap
