// The Whitted-style image pass: direct light recomputed per hit, indirect from the mesh.
#pragma once

#include <core/hdr_image.h>
#include <radiosity/direct_light.h>
#include <radiosity/patch_mesh.h>
#include <radiosity/solution.h>
#include <raytrace/camera.h>
#include <raytrace/embree_scene.h>
#include <scene/scene.h>

#include <functional>

namespace rayrad::raytrace {

/// Renders the camera's view in cd/m² (linear Rec.709). Per sample: the hit's emitted
/// luminance (front side of area lights) plus ρ/π (E_direct + E_indirect), with
/// E_direct from shadow rays (stratified on area lights) and virtual lights in the
/// mirrors, and E_indirect interpolated from the radiosity mesh's vertex values; rays
/// that hit mirrors or glass recurse (Whitted). Back faces are black. Each pixel has its
/// own random stream seeded by (seed, pixel), so the image does not depend on threads.
HdrImage render(const scene::Scene& scene, const radiosity::PatchMesh& mesh, const radiosity::RadiositySolution& solution,
                const radiosity::DirectLight& lights, const EmbreeScene& embree, const PinholeCamera& camera,
                const scene::RenderOptions& options, const std::function<void(double)>& onProgress = {});

/// Luminance (cd/m², RGB) seen along one ray; used by render() and by tests. Mirrors
/// (Ks × the reflected ray) and glass (Fresnel reflection + refraction) recurse up to
/// render.max_depth; beyond it a ray returns black.
Rgb shadeRay(const scene::Scene& scene, const radiosity::PatchMesh& mesh, const radiosity::RadiositySolution& solution,
             const radiosity::DirectLight& lights, const EmbreeScene& embree, const Vec3& origin, const Vec3& dir,
             int areaLightSamples, Random& rng, int depth = 0);

}  // namespace rayrad::raytrace
