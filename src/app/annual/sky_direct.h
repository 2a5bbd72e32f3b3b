// The sky's direct light at each sensor, by direction, on a fine subdivision of the sky.
#pragma once

#include <app/pipeline.h>
#include <scene/daylight/sky_patches.h>

#include <memory>
#include <utility>
#include <vector>

namespace rayrad::app {

/// The sky's direct light at each sensor by direction, finer than the solves' channels:
/// what each tent of a fine sky subdivision (and the ground) of 1 cd/m² gives the point
/// straight through the openings, E = Σ_y τ cosθ_x cosθ_y / r² ΔA V over points y on the
/// openings (32 × 32 a triangle), each direction shared among the tents around it.
struct DirectSkyCoefficients {
    std::shared_ptr<const scene::SkyPatches> patches;
    /// Per point: (tent, lx per cd/m²), the ground as tent patches->count().
    std::vector<std::vector<std::pair<uint32_t, float>>> terms;
};
DirectSkyCoefficients directSkyCoefficients(const PipelineRun& run, std::shared_ptr<const scene::SkyPatches> fine);

}  // namespace rayrad::app
