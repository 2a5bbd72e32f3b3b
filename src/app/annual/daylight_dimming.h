// Daylight-linked dimming: how far the scene's lamps can be dimmed, hour by hour, when
// each sensor's lamps make up only what the daylight leaves short of a target.
#pragma once

#include <app/annual/annual_study.h>
#include <app/pipeline.h>

#include <optional>
#include <vector>

namespace rayrad::app {

/// The scene's electric light alone at every sensor (lx, at full output): `run`'s lighting
/// solved with its daylight left out, then put back. Throws InputError when the scene has
/// no lamp.
std::vector<double> lampIlluminance(PipelineRun& run);

/// Per sensor, the mean over the occupied hours of the lamps' output needed,
/// d = min(1, max(0, (target − E_day) / E_lamps)) (ideal continuous dimming, lamps off
/// above the target): the share of the lamps' energy at full output all occupied hours.
/// Nothing for a sensor the lamps do not reach.
std::vector<std::optional<double>> dimmingShares(const AnnualStudy& study, const std::vector<double>& lamps,
                                                 double target);

}  // namespace rayrad::app
