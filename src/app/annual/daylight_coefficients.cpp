#include <app/annual/daylight_coefficients.h>

#include <core/input_error.h>
#include <core/progress.h>
#include <core/stage_report.h>
#include <scene/light_groups.h>

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <optional>

namespace rayrad::app {

namespace {

/// Solves the lighting of run.scene as it is now (its daylight one channel, a `sun` alone or
/// a sky), reusing and handing back the clusters; the sensors' values, or nothing when no
/// light comes in. `onSolution` sees the solution.
std::optional<std::vector<radiosity::SensorValue>> solveChannel(
    PipelineRun& run, radiosity::Clustering& clusters, bool sun,
    const std::function<void(const radiosity::RadiositySolution&)>& onSolution) {
    const radiosity::StageLog log{nullptr, nullptr, true, nullptr};
    radiosity::Lighting lighting = radiosity::solveDirect(run.scene, run.mesh, *run.embree, log);
    // A sky: no opening faces it (its unobstructed light through each, exactly; the
    // measured flux samples directions too sparsely for one tent). A sun: it reaches no
    // point of any opening.
    if (lighting.lights->openingCount() == 0 || (sun && !(lighting.lights->emittedFlux() > 0))) return std::nullopt;
    lighting.clustering = std::move(clusters);
    radiosity::solveIndirect(run.scene, run.mesh, *run.embree, lighting, log);
    auto values = radiosity::gatherSensors(run.scene, run.mesh, *run.embree, lighting, log);
    if (onSolution) onSolution(lighting.solution);
    clusters = std::move(lighting.clustering);
    return values;
}

}  // namespace

DaylightCoefficients solveDaylightCoefficients(PipelineRun& run, std::shared_ptr<const scene::SkyPatches> patches,
                                               std::shared_ptr<const scene::SkyPatches> fine,
                                               const std::vector<char>& sunNear, bool quiet,
                                               const ChannelSolutionHook& onSolution) {
    if (!run.scene.daylight)
        throw InputError(placeMessage(run.scene.file, "", "an annual study needs the scene's \"daylight\" (its axes "
                                                          "and ground) and openings"));
    const auto start = std::chrono::steady_clock::now();
    const double cpuStart = processCpuSeconds();
    DaylightCoefficients dc;
    dc.patches = std::move(patches);
    dc.points = run.scene.sensors.size();
    dc.indirect.assign(static_cast<size_t>(dc.channels()) * dc.points, 0.0);
    dc.sunSlot.assign(static_cast<size_t>(dc.patches->count()), -1);
    int suns = 0;
    for (char c : sunNear) suns += c != 0;

    scene::removeElectricLight(run.scene);
    const scene::Daylight base = *run.scene.daylight;
    radiosity::Clustering clusters;  // geometry only: built by the first channel, shared by the rest
    Progress progress("daylight coefficients", quiet);
    const int total = dc.channels() + suns;
    int done = 0;
    for (int c = 0; c < dc.channels(); ++c, ++done) {
        progress.update(static_cast<double>(done) / total, fmt::format("sky channel {} of {}", c + 1, dc.channels()));
        const int patch = c == dc.groundChannel() ? scene::SkyChannel::kGround : c;
        run.scene.daylight = scene::channelDaylight(base, {dc.patches, patch});
        const auto values = solveChannel(run, clusters, false, [&](const radiosity::RadiositySolution& solution) {
            if (onSolution) onSolution(c, -1, solution);
        });
        if (!values) continue;
        ++dc.solvedChannels;
        for (size_t i = 0; i < values->size(); ++i)
            dc.indirect[static_cast<size_t>(c) * dc.points + i] = luminance((*values)[i].indirect);
    }
    for (int j = 0; j < dc.patches->count(); ++j) {
        if (!sunNear[static_cast<size_t>(j)]) continue;
        progress.update(static_cast<double>(done) / total, fmt::format("sun {} of {}", done - dc.channels() + 1, suns));
        ++done;
        run.scene.daylight = scene::sunChannelDaylight(base, dc.patches->centre(j));
        const auto values = solveChannel(run, clusters, true, [&](const radiosity::RadiositySolution& solution) {
            if (onSolution) onSolution(-1, j, solution);
        });
        if (!values) continue;
        dc.sunSlot[static_cast<size_t>(j)] = dc.solvedSuns++;
        for (const auto& v : *values) dc.sunIndirect.push_back(luminance(v.indirect));
    }
    run.scene.daylight = base;
    dc.skyDirect = directSkyCoefficients(run, std::move(fine));
    dc.solveCpuSeconds = processCpuSeconds() - cpuStart;
    dc.solveWallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return dc;
}

}  // namespace rayrad::app
