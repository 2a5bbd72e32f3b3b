// Sensor names used twice: the one check for the scene file's sensors (the parser) and
// the surface grids' points added to them (the builder).
#pragma once

#include <scene/scene.h>

#include <cstddef>
#include <vector>

namespace rayrad::scene {

/// The index of each sensor whose name an earlier sensor has, the first such for each
/// name, in index order. A grid's (or work plane's, or surface grid's) points are named
/// NAME[i,j], distinct within it, so only the single sensors and the points of a grid
/// whose name another grid has too, or that a single sensor's name starts with, are
/// compared (a million points hashed took 0.23 s). For SensorDesc and Sensor.
template <class S>
std::vector<size_t> sensorsNamedAgain(const std::vector<S>& sensors);

}  // namespace rayrad::scene
