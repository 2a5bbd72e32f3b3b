// The scene file's "daylight" object: sky, sun, ground and the scene's axes.
#pragma once

#include <scene/daylight/daylight.h>
#include <scene/json_reader.h>

namespace rayrad::scene {

/// Reads "daylight" (see docs/scene-format.md): the axes "up" and "north", the "sky" (its
/// type and one scale), the "sun" (a place and time, or altitude and azimuth; its direct
/// normal illuminance) and "ground_reflectance". Errors go to the object's context.
Daylight parseDaylight(JsonObject d);

}  // namespace rayrad::scene
