// Writing a rendering to the files the user asked for (EXR linear, PNG/JPEG display).
#pragma once

#include <core/hdr_image.h>
#include <tonemap/display_transform.h>

#include <string>
#include <vector>

namespace rayrad::app {

/// Checks every output before any work: known extension, writable place.
void checkImageOutputs(const std::vector<std::string>& paths);

/// Writes the image to each path: .exr as linear cd/m², others through the display transform.
void writeImages(const std::vector<std::string>& paths, const HdrImage& image, const tonemap::DisplayOptions& display,
                 const std::string& description);

/// "out/cube.png" → "out/cube.snap03.png".
std::string snapshotPath(const std::string& path, int index);

}  // namespace rayrad::app
