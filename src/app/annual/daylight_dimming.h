// Daylight-linked dimming: how far the scene's lamps can be dimmed, hour by hour, when
// each sensor's lamps make up only what the daylight leaves short of a target.
#pragma once

#include <app/annual/annual_study.h>
#include <app/pipeline.h>

#include <optional>
#include <string>
#include <vector>

namespace rayrad::app {

/// The scene's electric light alone at every sensor (lx, at full output): `run`'s lighting
/// solved with its daylight left out, then put back; with `group`, that light group's
/// emitters alone (scene/light_groups.h). Throws InputError when the scene has no lamp.
std::vector<double> lampIlluminance(PipelineRun& run, const std::optional<std::string>& group = std::nullopt);

/// Per sensor, the mean over the occupied hours of the lamps' output needed,
/// d = min(1, max(0, (target − E_day) / E_lamps)) (ideal continuous dimming, lamps off
/// above the target): the share of the lamps' energy at full output all occupied hours.
/// Nothing for a sensor the lamps do not reach.
std::vector<std::optional<double>> dimmingShares(const AnnualStudy& study, const std::vector<double>& lamps,
                                                 double target);

/// A light group dimmed by the daylight at one control point, as a photosensor would:
/// in each occupied hour d = min(1, max(0, (target − E_day) / E_g)) at that point.
struct GroupDimming {
    std::string group;              ///< "" for the lamps in no group
    size_t control = 0;             ///< the sensor the group answers to
    double controlIlluminance = 0;  ///< E_g there at full output, lx
    double energyShare = 0;         ///< the mean of d over the occupied hours
};

/// Per light group (`groups`, each with its light at every sensor at full output,
/// lampIlluminance) its control point: the sensor `controls` names for it (GROUP=SENSOR),
/// else the sensor it lights most. Throws InputError for a control that names an unknown
/// group or sensor.
std::vector<GroupDimming> dimmingControls(const std::vector<scene::Sensor>& sensors,
                                          const std::vector<std::string>& groups,
                                          const std::vector<std::vector<double>>& groupLamps,
                                          const std::vector<std::string>& controls);

/// Each group's energy share when it dims to `target` at its control point.
void dimGroups(const AnnualStudy& study, double target, std::vector<GroupDimming>& groups);

}  // namespace rayrad::app
