// Warnings for daylight that will not light the scene as meant: no openings, openings
// wound backwards or walled up, a sun below the horizon.
#pragma once

#include <raytrace/embree_scene.h>
#include <scene/scene.h>

#include <string>
#include <vector>

namespace rayrad::app {

/// One line each: a sky with no opening to come in through (only the sun lights the scene);
/// an opening whose front (the room's side) looks into the open — wound backwards — or
/// whose back is covered within a few centimetres, so no sky reaches it; a sun given
/// a direct illuminance but below the horizon (no direct sun).
std::vector<std::string> daylightWarnings(const scene::Scene& scene, const raytrace::EmbreeScene& embree);

}  // namespace rayrad::app
