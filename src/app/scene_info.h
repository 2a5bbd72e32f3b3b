// rayrad info: what a scene holds and what a run of it will cost, before any work; for a
// photometric file, its photometry.
#pragma once

#include <app/command_line.h>
#include <scene/overrides.h>

#include <string>
#include <vector>

namespace rayrad::app {

/// Prints the counts (materials, surfaces, patches, clusters, lights, sensors, views, mirror
/// images), the expected peak memory, warnings and the stages a run needs; for a
/// photometric file its photometry and, asked, its UGR table. Returns 0.
int printSceneInfo(const InfoArgs& args, const std::vector<scene::Override>& overrides);

}  // namespace rayrad::app
