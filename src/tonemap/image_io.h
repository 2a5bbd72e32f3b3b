// Image files: EXR (linear cd/m²) and 8-bit PNG/JPEG, encoded in memory through OpenImageIO
// in the image module (tonemap/image_library.h; no library writes or exits on its own) and
// written by core/output_file.
#pragma once

#include <core/hdr_image.h>

#include <cstdint>
#include <string>
#include <vector>

namespace rayrad::tonemap {

/// True for the extensions we write as linear floats (.exr); PNG/JPEG are display images.
bool isHdrFormat(const std::string& path);
/// Throws OutputError unless the extension is one we can write (.exr .png .jpg .jpeg).
void checkImageFormat(const std::string& path);

/// The bytes of an EXR file: linear Rec.709 in absolute luminance (cd/m²), 32-bit
/// floats (half floats overflow at 65504 cd/m²), with metadata saying so, and no time
/// stamp (the same input gives the same bytes). `path` names it in messages.
std::string encodeExr(const std::string& path, const HdrImage& image, const std::string& description,
                      const std::vector<std::pair<std::string, std::string>>& attributes = {});

/// The bytes of a PNG or JPEG file (by `path`'s extension) of display-encoded 8-bit RGB
/// (already tone mapped and encoded); `description` (how it was tone mapped and white
/// balanced) goes into the file's ImageDescription.
std::string encodeDisplayImage(const std::string& path, int width, int height, const std::vector<uint8_t>& rgb8,
                               const std::string& description = "");

/// encodeExr, then written safely (core/output_file.h).
void writeExr(const std::string& path, const HdrImage& image, const std::string& description);
/// encodeDisplayImage, then written safely.
void writeDisplayImage(const std::string& path, int width, int height, const std::vector<uint8_t>& rgb8);

/// Reads any image OIIO can read as linear floats as stored (tests, image diffs); with
/// `attributes`, also its string attributes whose names start with "rayrad:".
HdrImage readImage(const std::string& path, std::vector<std::pair<std::string, std::string>>* attributes = nullptr);

/// "OpenImageIO 2.4.7, OpenColorIO 2.1.2 (loaded when …)": the versions this build was
/// compiled against, told without loading them.
std::string libraryVersions();

}  // namespace rayrad::tonemap
