// Coincident surfaces: two surfaces in one place, facing the same way (a floor modelled
// twice, a wall on a wall). Both receive the same light and both reflect it, so the room
// holds more light than its lamps give: the energy account books it as "not accounted".
#pragma once

#include <radiosity/radiosity.h>
#include <scene/scene.h>

#include <optional>
#include <string>

namespace rayrad::app {

/// A warning naming the pair of surface groups with the most coincident area (m²) and how
/// much coincides in all, or nothing when no patch's centroid lies on another surface's
/// patch in the same plane, facing the same way, or when what does is under 1/1000 of the
/// scene's area (slivers where modelled parts overlap by a hair). Two-sided surfaces' backs face the other
/// way and do not count.
std::optional<std::string> coincidentSurfacesWarning(const scene::Scene& scene, const radiosity::PatchMesh& mesh);

}  // namespace rayrad::app
