// When a scene is too small for its radiosity work to be shared among threads.
#pragma once

#include <radiosity/mesh/patch_mesh.h>

#include <cstddef>

namespace rayrad::radiosity {

/// Below this many patches a shot, or a point gather's sum over the scene's sources, holds
/// about 0.1 ms of work: less than waking and joining the other threads costs, and those
/// spin while they wait. The shooting then runs on one thread and a gather sums on the
/// thread that asked (the cube at 1 200 patches: its shooting took 0.29 CPU-s for 0.14 s
/// wall on two threads, 0.16 for 0.16 on one). Results do not depend on the thread count.
constexpr size_t kOneThreadBelowPatches = 2000;

inline bool tooSmallToShare(const PatchMesh& mesh) { return mesh.patches.size() < kOneThreadBelowPatches; }

}  // namespace rayrad::radiosity
