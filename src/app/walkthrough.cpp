#include <app/walkthrough.h>

#include <core/input_error.h>
#include <raytrace/ray_tracer.h>
#include <tonemap/tone_operators.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace rayrad::app {

std::pair<int, int> parseFrames(const std::string& text, int count, const std::string& sceneFile) {
    if (count == 0)
        throw InputError(
            placeMessage(sceneFile, "--frames", "the scene has no \"camera_path\" (docs/scene-format.md#camera-path)"));
    if (text == "all") return {0, count - 1};
    const auto number = [&](const std::string& s) {
        size_t used = 0;
        long long v = -1;
        try {
            v = std::stoll(s, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (s.empty() || used != s.size() || v < 0)
            throw InputError(
                placeMessage("", "--frames", "expected all, K or A:B (frame numbers from 0), got \"" + text + "\""));
        if (v >= count)
            throw InputError(
                placeMessage(sceneFile, "--frames",
                             fmt::format("frame {} is beyond the path's {} frames (0 to {})", v, count, count - 1)));
        return static_cast<int>(v);
    };
    const auto colon = text.find(':');
    if (colon == std::string::npos) {
        const int k = number(text);
        return {k, k};
    }
    const int a = number(text.substr(0, colon)), b = number(text.substr(colon + 1));
    if (b < a)
        throw InputError(placeMessage("", "--frames", "the last frame comes before the first in \"" + text + "\""));
    return {a, b};
}

std::string framePath(const std::string& path, int frame) {
    const std::filesystem::path p(path);
    return (p.parent_path() / fmt::format("{}.{:04d}{}", p.stem().string(), frame, p.extension().string())).string();
}

double solutionAdaptationLuminance(const PipelineRun& run) {
    return 0.18 * raytrace::compressionLuminance(run.scene, run.mesh, run.lighting.solution);  // L_c = L̄ / 0.18
}

double viewsAdaptationLuminance(PipelineRun& run, const std::vector<scene::Camera>& cameras,
                                const PipelineOptions& options) {
    constexpr size_t kSamples = 8;
    constexpr int kWidth = 64;
    if (cameras.empty()) return 0;
    PipelineOptions sampling = options;
    sampling.quiet = true;
    sampling.rowBegin = 0, sampling.rowEnd = -1;
    const size_t count = std::min(kSamples, cameras.size());
    const scene::RenderOptions saved = run.scene.render;
    run.scene.render.samplesPerPixel = 1;
    HdrImage seen;  // every sample's pixels in one row, for the log-average
    seen.height = 1;
    for (size_t i = 0; i < count; ++i) {
        scene::Camera c = cameras[count == 1 ? 0 : i * (cameras.size() - 1) / (count - 1)];
        c.height = std::max(1, static_cast<int>(std::lround(static_cast<double>(kWidth) * c.height / c.width)));
        c.width = kWidth;
        const auto view = renderCamera(run, fmt::format("adaptation sample {}", i + 1), c, sampling);
        seen.pixels.insert(seen.pixels.end(), view.image.pixels.begin(), view.image.pixels.end());
    }
    run.scene.render = saved;
    seen.width = static_cast<int>(seen.pixels.size());
    return tonemap::logAverageLuminance(seen);  // over the lit pixels; 0 when none
}

tonemap::DisplayOptions steadyDisplay(double average, tonemap::DisplayOptions display) {
    if (!(average > 0)) return display;  // nothing lit to adapt to: each image as usual
    if (display.autoExposure) {
        display.exposureStops += std::log2(0.18 / average);
        display.autoExposure = false;
    }
    if (!display.tone.worldAdaptation) display.tone.worldAdaptation = average;
    return display;
}

}  // namespace rayrad::app
