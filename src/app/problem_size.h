// What a scene's settings will cost, estimated before the work is allocated or started:
// absurd settings are an error naming the setting, costly ones a warning with the figure.
#pragma once

#include <radiosity/radiosity.h>
#include <scene/scene.h>

#include <string>
#include <vector>

namespace rayrad::app {

/// Before premeshing: throws InputError (naming `file` and the setting) when the premesh
/// would make more than radiosity.max_patches patches (estimatePatchCount()); returns
/// the estimate.
double checkPatchCount(const std::string& file, const scene::Scene& scene);

/// Expected peak memory of a run, bytes: the process's base, the image libraries when it
/// reads or writes `images`, the patches, and a few bytes per cluster and mirror image.
double estimatePeakBytes(size_t patches, size_t clusters, size_t mirrorImages, bool images);

/// After premeshing, one line each: a cluster voxel much smaller than the patches (every
/// patch its own cluster, so each shot visits every patch), and sensor gathers that will
/// take at least ten CPU-minutes. Throws InputError when the voxel grid cannot be indexed.
std::vector<std::string> costWarnings(const std::string& file, const scene::Scene& scene,
                                      const radiosity::PatchMesh& mesh, bool gatherSensors);

}  // namespace rayrad::app
