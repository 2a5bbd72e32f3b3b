// Daylight coefficients: what each sky patch's tent (and the ground) of 1 cd/m² and a sun
// of 1 lx at each patch's centre add at every sensor by interreflection, from one radiosity
// solve per channel; the sky's direct light beside them (sky_direct.h).
#pragma once

#include <app/annual/sky_direct.h>
#include <app/pipeline.h>
#include <scene/daylight/sky_patches.h>

#include <functional>
#include <memory>
#include <vector>

namespace rayrad::app {

struct DaylightCoefficients {
    std::shared_ptr<const scene::SkyPatches> patches;
    size_t points = 0;  ///< the scene's sensors (grid points included), in their order
    /// Interreflected light, lx at point i per cd/m² of channel c: [c · points + i].
    /// Channels: the sky patches' tents 0 … P−1 (SkyPatches::weight), then the ground.
    std::vector<double> indirect;
    /// The direct light of the sky and the ground, on a finer subdivision.
    DirectSkyCoefficients skyDirect;
    /// lx of interreflected light at point i per lx of direct normal illuminance from a sun
    /// at the centre of patch j: [sunSlot[j] · points + i]; sunSlot[j] −1 where no sun was
    /// solved (the year's sun does not come near, or no opening lets it in: zero).
    std::vector<double> sunIndirect;
    std::vector<int> sunSlot;
    int solvedChannels = 0, solvedSuns = 0;  ///< solves run (channels no opening lets in are zero, not solved)
    double solveCpuSeconds = 0, solveWallSeconds = 0;

    int channels() const { return patches->count() + 1; }
    int groundChannel() const { return patches->count(); }
    double indirectAt(int c, size_t i) const { return indirect[static_cast<size_t>(c) * points + i]; }
    double sunIndirectAt(int patch, size_t i) const {
        const int slot = sunSlot[static_cast<size_t>(patch)];
        return slot < 0 ? 0.0 : sunIndirect[static_cast<size_t>(slot) * points + i];
    }
};

/// Solves `run`'s scene (prepared: preparePipeline; its daylight is replaced, its electric
/// light removed) once per channel, sharing the mesh, the visibility and the clusters:
/// each sky patch's tent, the ground, and a sun at the centre of each patch `sunNear`
/// marks. Each solve's direct light and interreflection are those of an ordinary daylight
/// solve under that sky; the sensors keep its interreflected light, their direct light
/// comes from directSkyCoefficients on the `fine` patches. A progress line unless `quiet`.
/// `onSolution` (if given) sees each solve's whole solution: channel c (sky tents, then the
/// ground) with sunPatch −1, or the sun at the centre of patch sunPatch with c −1.
using ChannelSolutionHook = std::function<void(int channel, int sunPatch, const radiosity::RadiositySolution&)>;
DaylightCoefficients solveDaylightCoefficients(PipelineRun& run, std::shared_ptr<const scene::SkyPatches> patches,
                                               std::shared_ptr<const scene::SkyPatches> fine,
                                               const std::vector<char>& sunNear, bool quiet,
                                               const ChannelSolutionHook& onSolution = {});

}  // namespace rayrad::app
