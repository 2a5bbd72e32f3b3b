// Sensors, sensor grids, work planes and observers: the scene parser's part for where illuminance is
// reported (scene_parser.cpp reads the rest).
#pragma once

#include <scene/json_reader.h>
#include <scene/scene_desc.h>

#include <vector>

namespace rayrad::scene {

/// One sensor: name (default "S<index>"), position, normal, optional reference values.
SensorDesc parseSensor(JsonObject s, int index);

/// A grid: counts[0] × counts[1] sensors at the cell centres of the parallelogram
/// (origin, u, v), appended to `out`.
void parseSensorGrid(JsonObject g, int index, std::vector<SensorDesc>& out);

/// A horizontal work plane over a room outline (EN 12464-1 spacing by default), appended
/// to `out`.
void parseWorkPlane(JsonObject w, int index, std::vector<SensorDesc>& out);

/// A grid on surfaces of the scene (a material's faces), checked here and expanded by
/// the builder (scene/surface_grids.h).
SurfaceGridDesc parseSurfaceGrid(JsonObject g, int index);

/// One observer: "name" (default "O<index>"), "position", "direction" or "look_at", "up"
/// (default [0, 1, 0]), and "ugr_limit" or "task" (ugrTaskLimit's names).
Observer parseObserver(JsonObject o, int index);

/// EN 12464-1 (after EN 12193): the grid spacing for an area whose longer side is d
/// metres, p = 0.2 · 5^log10(d) m (0.2 m at 1 m, 1 m at 10 m, 5 m at 100 m), at most 10 m.
double standardGridSpacing(double d);

}  // namespace rayrad::scene
