// Where an image's pixels land: the surfaces a camera sees first through random pixels,
// for holding an image's indirect light against a final gather there.
#pragma once

#include <raytrace/embree_scene.h>
#include <scene/scene.h>

#include <cstdint>
#include <vector>

namespace rayrad::raytrace {

/// A reflecting surface point a camera sees through a pixel.
struct ViewSample {
    uint32_t patch = 0;
    Vec3 position{0.0};  ///< on the patch's plane, m
    Vec3 normal{0.0};    ///< the patch's (the side the camera sees)
};

/// What `camera` sees first through `count` random pixels (from `seed`), where that is a
/// reflecting patch that does not emit; where the ray meets the back of a surface, the
/// front of one coinciding with it, as the ray tracer shows. Pixels that show the sky, a
/// mirror, glass, a lamp or the black back of a one-sided surface are left out and counted
/// in `missed`.
std::vector<ViewSample> viewSamples(const scene::Scene& scene, const scene::Camera& camera,
                                    const radiosity::PatchMesh& mesh, const EmbreeScene& embree, int count,
                                    uint64_t seed, int& missed);

}  // namespace rayrad::raytrace
