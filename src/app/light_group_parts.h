// Each light group's part of every sensor value: one solve per group (the light is linear
// in the emission), so a designer can dim a group afterwards by scaling its part.
#pragma once

#include <app/pipeline.h>
#include <app/sensor_table.h>
#include <radiosity/radiosity.h>

#include <string>
#include <vector>

namespace rayrad::app {

struct LightGroupParts {
    std::vector<std::string> groups;                         ///< "" is the emitters in no group
    std::vector<std::vector<radiosity::SensorValue>> parts;  ///< parts[g][i]: sensor i lit by group g alone
    std::vector<radiosity::GroupSolution> solutions;         ///< each group's solution, when kept (solve --save)
};

/// True when an emitter of the scene names a light group.
bool hasLightGroups(const scene::SceneDesc& desc);

/// Solves the scene once per group (sensors only, no image, `base`'s overrides), with the
/// full solve's ΔI_max; `keepSolutions`: also each group's radiosity solution.
LightGroupParts solveLightGroups(const std::string& sceneFile, const PipelineOptions& base, const PipelineRun& full,
                                 const std::vector<std::string>& groups, bool keepSolutions = false);

/// The terminal table: per sensor, each group's total illuminance, their sum and its
/// difference from the full solve (the solver's tolerance: dimming a group by scaling its
/// part agrees with re-solving to that).
std::string lightGroupTable(const std::vector<SensorResult>& full, const LightGroupParts& parts);

/// The largest |Σ groups − full| / full over the sensors with light, for the summary.
double largestGroupSumDifference(const std::vector<SensorResult>& full, const LightGroupParts& parts);

/// CSV: sensor,group,direct_lx,indirect_lx,total_lx (group "" written as "(none)").
std::string lightGroupCsv(const std::vector<SensorResult>& full, const LightGroupParts& parts);

/// Beside the sensor CSV: "out/room.csv" → "out/room.groups.csv".
std::string lightGroupPath(const std::string& sensorCsvPath);

}  // namespace rayrad::app
