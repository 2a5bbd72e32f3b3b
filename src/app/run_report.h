// The run's machine-readable account (--report FILE.json).
#pragma once

#include <app/light_group_parts.h>
#include <app/pipeline.h>

#include <string>

namespace rayrad::app {

/// JSON: counts, stages with time and peak memory, solver statistics, energy balance,
/// sensors with references, grid statistics and, when the run solved light groups
/// (`groups` not null), each group's part of every sensor ("light_groups": groups in the
/// order of "parts"; null is the lights in no group).
std::string runReportJson(const PipelineRun& run, const std::string& sceneFile, const LightGroupParts* groups);

}  // namespace rayrad::app
