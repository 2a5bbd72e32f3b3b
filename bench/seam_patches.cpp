// Benchmark: the solution's patch values beside a concave seam against
// the exact sum of the same solution at their centroids. For the Cornell box's ceiling and
// back wall, the patches within 70 mm of the seam between them: the solve's indirect
// illuminance E_P (collocated at the centroid) and a final gather at the centroid with
// every patch patch-constant, its own form factor and its own visibility ray (no far
// nodes, no shared rays: Σ_j π L_j F(c_P → j) V, what E_P converges to without
// clustering). Prints one row per distance from the seam with the worst and the median
// relative difference. A difference here is the solver's, not the display's.
// Usage: build/bench/seam_patches [key=value ...]   (scene settings, as with --set; the
//        scene's own max_edge is 0.05 m)
#include "bench_main.h"

#include <app/pipeline.h>
#include <radiosity/gather/gather.h>
#include <scene/scene_parser.h>

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <vector>

using namespace rayrad;

namespace {
const char* const kUsage =
    "usage: seam_patches [key=value ...]   (scene settings, as with rayrad's --set)\n"
    "The Cornell box's solved patch values within 70 mm of its ceiling's seam with the back\n"
    "wall against an exact sum of the same solution at their centroids, by distance.\n";

int seamPatches(int argc, char** argv) {
    constexpr double kCeilingY = 0.5488, kBackZ = 0.5592, kBand = 0.07;  // m
    app::PipelineOptions options;
    options.quiet = true;
    for (int i = 1; i < argc; ++i) options.overrides.push_back(scene::parseOverride(argv[i]));
    const auto start = std::chrono::steady_clock::now();
    const app::PipelineRun run =
        app::runPipeline(std::string(RAYRAD_SOURCE_DIR) + "/scenes/cornell/cornell.json", options);
    const double solveSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    radiosity::GatherOptions exact =
        radiosity::GatherOptions::plain();  // every patch on its own: levels 0, no far nodes, no shared rays
    exact.sharedRays = false;
    const radiosity::Gatherer gatherer(run.scene, run.mesh, run.lighting.clustering, run.lighting.solution, *run.embree,
                                       exact);
    radiosity::GatherMemo memo;
    // (surface, mm from the seam rounded to 0.1) → relative differences, %
    std::map<std::pair<std::string, double>, std::vector<double>> rows;
    for (size_t i = 0; i < run.mesh.patches.size(); ++i) {
        const radiosity::Patch& p = run.mesh.patches[i];
        const bool wall = p.normal.z < -0.99 && kCeilingY - p.centroid.y < kBand;
        const bool ceiling = p.normal.y < -0.99 && p.centroid.y > kCeilingY - 0.01 && kBackZ - p.centroid.z < kBand;
        if (!wall && !ceiling) continue;
        const double mm = std::round(10000 * (wall ? kCeilingY - p.centroid.y : kBackZ - p.centroid.z)) / 10;
        const double gathered = luminance(gatherer.indirectAt(p.centroid, p.normal, memo));
        if (gathered > 0)
            rows[{wall ? "back wall" : "ceiling", mm}].push_back(
                100 * (luminance(run.lighting.solution.indirect[i]) / gathered - 1));
    }
    fmt::print(
        "patches beside the Cornell ceiling's seam with the back wall: the solve's E_P against the exact sum at "
        "the centroid (solve {:.1f} s wall, {} patches)\n",
        solveSeconds, run.mesh.patches.size());
    fmt::print("{:<10} {:>8} {:>8} {:>10} {:>10}\n", "surface", "mm", "patches", "worst %", "median %");
    for (auto& [key, diffs] : rows) {
        std::sort(diffs.begin(), diffs.end(), [](double a, double b) { return std::abs(a) < std::abs(b); });
        fmt::print("{:<10} {:>8.1f} {:>8} {:>+10.2f} {:>+10.2f}\n", key.first, key.second, diffs.size(), diffs.back(),
                   diffs[diffs.size() / 2]);
    }
    return 0;
}
}  // namespace

int main(int argc, char** argv) {
    return rayrad::bench::runBench("seam_patches", kUsage, argc, argv, [&] { return seamPatches(argc, argv); });
}
