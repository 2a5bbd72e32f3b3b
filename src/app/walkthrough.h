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

/// The solution's area-weighted log-average luminance of the diffuse surfaces, cd/m²
/// (reflected light: emitters do not pull it up), 0 for a black solution.
double solutionAdaptationLuminance(const PipelineRun& run);

/// `display` with what it would take from each image taken instead from the solution:
/// auto exposure maps the solution's log-average luminance L_avg to 0.18 (plus the
/// user's stops), and the tone operators' world adaptation L_wa is L_avg unless given.
/// Every frame of a walkthrough (and a baked export) is then exposed alike.
tonemap::DisplayOptions steadyDisplay(const PipelineRun& run, tonemap::DisplayOptions display);

}  // namespace rayrad::app
