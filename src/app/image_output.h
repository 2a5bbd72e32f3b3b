// Writing a rendering to the files the user asked for (EXR linear, PNG/JPEG display).
#pragma once

#include <core/hdr_image.h>
#include <core/output_file.h>
#include <tonemap/display_transform.h>

#include <string>
#include <vector>

namespace rayrad::app {

/// Checks every image output before any work (known extension, a path that can be
/// written) and adds it to `files`.
void addImageOutputs(const std::vector<std::string>& paths, OutputFiles& files);

/// Encodes the image for each path (.exr: `image`, linear cd/m²; others: `forDisplay`,
/// the range-compressed average, through the display transform, each checked by
/// checkDisplayImage) and gives the bytes to `files`; nothing is written until
/// files.commit().
void stageImages(const std::vector<std::string>& paths, const HdrImage& image, const HdrImage& forDisplay,
                 const tonemap::DisplayOptions& display, const std::string& description, OutputFiles& files);

/// "out/cube.png" → "out/cube.snap03.png".
std::string snapshotPath(const std::string& path, int index);

/// How the display options expose the image, for messages: "auto", "auto +2 stops", "-40 stops".
std::string describeExposure(const tonemap::DisplayOptions& display);

}  // namespace rayrad::app
