// Image files through OpenImageIO: encoded in memory (no library writes or exits on its own),
// read as linear floats (tonemap/image_io.h is the caller's side and says what each does).
#pragma once

#include <core/hdr_image.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace rayrad::image_module {

std::string encodeExr(const std::string& path, const HdrImage& image, const std::string& description,
                      const std::vector<std::pair<std::string, std::string>>& attributes);
std::string encodeDisplayImage(const std::string& path, int width, int height, const std::vector<uint8_t>& rgb8,
                               const std::string& description);
HdrImage readImage(const std::string& path, std::vector<std::pair<std::string, std::string>>* attributes);
/// "OpenImageIO 2.4.7, OpenColorIO 2.1.2": the versions this module runs with.
std::string libraryVersions();

}  // namespace rayrad::image_module
