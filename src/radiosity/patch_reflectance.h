// A patch's diffuse reflectance: its material's, or where its surface is textured,
// ρ(x) = reflectance · T(u, v) at a point and that averaged over the patch for the radiosity.
#pragma once

#include <radiosity/patch_mesh.h>
#include <scene/scene.h>

namespace rayrad::radiosity {

/// ρ of patch i as the radiosity sees it, per channel, in [0, 1).
inline Rgb patchReflectance(const scene::Scene& scene, const PatchMesh& mesh, size_t i) {
    return mesh.texturedReflectance.empty() ? scene.materials[mesh.patches[i].material].reflectance
                                            : Rgb(mesh.texturedReflectance[i]);
}

/// ρ at barycentric (u, v) of patch i (the point (1−u−v) c0 + u c1 + v c2): the material's
/// reflectance times its texture there, each channel clamped to kMaxFileReflectance.
Rgb reflectanceAt(const scene::Scene& scene, const PatchMesh& mesh, size_t i, double u, double v);

/// Fills mesh.texturedReflectance when the scene has textures: each textured patch's mean
/// of ρ over its triangle, from the texels (decoded, not interpolated) at the centroids of
/// a lattice of k² sub-triangles, k = clamp(4 × the patch's longest edge in texels, 4, 64),
/// untextured patches their material's reflectance. Needs scene.textureImages.
void computeTexturedReflectance(const scene::Scene& scene, PatchMesh& mesh);

}  // namespace rayrad::radiosity
