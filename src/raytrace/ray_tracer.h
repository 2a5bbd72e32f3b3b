// The Whitted-style image pass: direct light recomputed per hit, indirect from the mesh.
#pragma once

#include <core/hdr_image.h>
#include <radiosity/radiosity.h>
#include <raytrace/camera.h>
#include <raytrace/embree_scene.h>
#include <raytrace/ray_cone.h>
#include <scene/scene.h>

#include <functional>

namespace rayrad::raytrace {

/// The average a display image is made from: each sample weighted by 1 / (1 + L_s / L_c)
/// (L_s its luminance), i.e. the samples range-compressed before they are averaged and
/// the average expanded again. A pixel half covered by a lamp 1 000 × brighter than L_c
/// then reads about L_c (not 500 L_c, which any display shows as white), so an emitter's
/// edge shades off over its pixels as the coverage does. Pixels of one level are unchanged.
struct DisplayAverage {
    double compressionLuminance = 0;  ///< L_c, cd/m² (0: off)
    HdrImage image;                   ///< filled by render()
};

/// L_c for a scene: the display white under the key-value exposure, L̄ / 0.18, with L̄ the
/// area-weighted log-average of the patches' reflected luminance (cd/m²).
double compressionLuminance(const scene::Scene& scene, const radiosity::PatchMesh& mesh,
                            const radiosity::RadiositySolution& solution);

/// Renders the camera's view in cd/m² (linear Rec.709). Per sample: the hit's emitted
/// luminance (front side of area lights) plus ρ/π (E_direct + E_indirect), with
/// E_direct from shadow rays (stratified on area lights) and virtual lights in the
/// mirrors, and E_indirect interpolated from the radiosity mesh's vertex values; rays
/// that hit mirrors or glass recurse (Whitted). Back faces are black. Each pixel has its
/// own random stream seeded by (seed, pixel), so the image does not depend on threads.
/// Only rows [rowBegin, rowEnd) are traced (the rest stay black; rowEnd −1: to the last):
/// a tile of a render has the same pixels as the whole. `gatherer` (or null): E_indirect
/// is a final gather at each hit instead (render.indirect "gather").
HdrImage render(const scene::Scene& scene, const radiosity::PatchMesh& mesh,
                const radiosity::RadiositySolution& solution, const radiosity::DirectLight& lights,
                const EmbreeScene& embree, const ImageCamera& camera, const scene::RenderOptions& options,
                const std::function<void(double)>& onProgress = {}, DisplayAverage* display = nullptr, int rowBegin = 0,
                int rowEnd = -1, const radiosity::Gatherer* gatherer = nullptr);

/// A final gather at each hit (render.indirect "gather") and the memo of the corner
/// values it re-gathers: render() keeps one per image row, so a row's pixels share them
/// and the image does not depend on the threads.
struct HitGather {
    const radiosity::Gatherer& gatherer;
    radiosity::GatherMemo& memo;
};

/// Luminance (cd/m², RGB) seen along one ray; used by render() and by tests. Mirrors
/// (Ks × the reflected ray) and glass (Fresnel reflection + refraction) recurse up to
/// render.max_depth; beyond it a ray returns black. `cone` is the ray's footprint, which
/// filters textures at the hit (zero: a point). `gather` (or null): E_indirect from a
/// final gather at the hit instead of the mesh. `pixel` (or null): the pixel's memo of the
/// far lights' shadows, shared by its samples' first hits on one patch (not by the hits
/// behind a mirror or glass).
Rgb shadeRay(const scene::Scene& scene, const radiosity::PatchMesh& mesh, const radiosity::RadiositySolution& solution,
             const radiosity::DirectLight& lights, const EmbreeScene& embree, const Vec3& origin, const Vec3& dir,
             int areaLightSamples, Random& rng, const RayCone& cone = {}, int depth = 0,
             const HitGather* gather = nullptr, radiosity::PixelLightMemo* pixel = nullptr);

/// The patch a ray along `dir` from `origin` shows at its hit h on a patch: h, met from the
/// front; met from behind, the front of a surface coinciding with it (back-to-back quads, a
/// two-sided surface's two sides) within a few epsilons of it; else nothing (not found):
/// surfaces are one-sided, black behind. `dir` need not be unit (h.t is in its lengths).
Hit seenSide(const radiosity::PatchMesh& mesh, const EmbreeScene& embree, const Vec3& origin, const Vec3& dir,
             const Hit& h);

}  // namespace rayrad::raytrace
