// render --frames: a walkthrough's frames along the scene's camera path, where each one's
// image goes, and one display adaptation for all of them so the sequence does not flicker.
#pragma once

#include <app/pipeline.h>
#include <tonemap/display_transform.h>

#include <string>
#include <utility>

namespace rayrad::app {

/// The frames `text` asks for, first and last inclusive: "all", "K" or "A:B" (0-based) of
/// a path of `count` frames. Throws InputError (naming --frames and `sceneFile`) for a
/// malformed range, one outside the path, or a scene without "camera_path".
std::pair<int, int> parseFrames(const std::string& text, int count, const std::string& sceneFile);

/// Where frame k goes: "out/walk.png", 7 → "out/walk.0007.png" (at least 4 digits).
std::string framePath(const std::string& path, int frame);

/// The log-average luminance (cd/m²) of what `cameras` see: up to 8 of them, evenly
/// spaced, rendered 64 pixels wide at 1 sample (stage "ray trace (adaptation sample K)"),
/// their lit pixels averaged in log. The same for every process that renders part of a
/// walkthrough, so a farm's frames are exposed alike. 0 when they see nothing lit.
double viewsAdaptationLuminance(PipelineRun& run, const std::vector<scene::Camera>& cameras, const PipelineOptions& options);

/// The solution's area-weighted log-average reflected luminance of its patches, cd/m²
/// (for a scene without a camera to sample; dark hidden surfaces pull it down).
double solutionAdaptationLuminance(const PipelineRun& run);

/// `display` with what it would take from each image taken from `average` (cd/m²)
/// instead: auto exposure maps it to 0.18 (plus the user's stops), and the tone
/// operators' world adaptation L_wa is `average` unless given. Every frame of a
/// walkthrough (and a baked export) is then exposed alike.
tonemap::DisplayOptions steadyDisplay(double average, tonemap::DisplayOptions display);

}  // namespace rayrad::app
