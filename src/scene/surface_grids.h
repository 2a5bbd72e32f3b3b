// Grids on surfaces of the scene: a designer's "calculation surface" on a desk top, a wall
// or a floor, wherever the geometry puts it (boxes, polygons, imported meshes).
#pragma once

#include <scene/scene.h>
#include <scene/scene_desc.h>

#include <vector>

namespace rayrad::scene {

/// The points of a surface grid, from the built scene's faces of `grid.material` (world
/// space). Faces that lie in one plane and touch (share a corner) make one surface; each
/// surface of at least `grid.minArea` gets its own grid of equal cells over its extent in the plane — spacing
/// `grid.spacing`, or EN 12464-1's for its longer side — with a point at every cell centre
/// that lies on one of its faces, raised `grid.offset` along the face normal and facing
/// that way. One surface: grid `name`, points `name[i,j]`; several: `name#1`, `name#2`, …
/// in the order their first face appears. Throws InputError naming the grid.
std::vector<Sensor> surfaceGridSensors(const Scene& scene, const SurfaceGridDesc& grid);

}  // namespace rayrad::scene
