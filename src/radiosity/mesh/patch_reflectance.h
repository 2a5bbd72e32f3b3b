// A patch's diffuse reflectance: its material's, or where its surface is textured,
// ρ(x) = reflectance · T(u, v) at a point and that averaged over the patch for the radiosity.
#pragma once

#include <radiosity/mesh/patch_mesh.h>
#include <scene/scene.h>

namespace rayrad::radiosity {

/// ρ of patch i as the radiosity sees it, per channel, in [0, 1).
inline Rgb patchReflectance(const scene::Scene& scene, const PatchMesh& mesh, size_t i) {
    return mesh.texturedReflectance.empty() ? scene.materials[mesh.patches[i].material].reflectance
                                            : Rgb(mesh.texturedReflectance[i]);
}

/// ρ at barycentric (u, v) of patch i (the point (1−u−v) c0 + u c1 + v c2): the material's
/// reflectance times its texture there, each channel clamped to kMaxFileReflectance. The
/// texture is filtered over the footprint whose two axes are `footprintA` and `footprintB`
/// (world-space vectors in the patch's plane, m; zero: a point).
Rgb reflectanceAt(const scene::Scene& scene, const PatchMesh& mesh, size_t i, double u, double v,
                  const Vec3& footprintA = Vec3(0.0), const Vec3& footprintB = Vec3(0.0));

/// A world-space displacement d in patch i's plane as the change of its texture
/// coordinates: with the corners' edges e1 = c1 − c0, e2 = c2 − c0 and texture edges
/// t1 = uv1 − uv0, t2 = uv2 − uv0, d = α e1 + β e2 solved in the least-squares sense
/// (the Gram matrix of e1, e2), and Δuv = α t1 + β t2.
glm::dvec2 textureChange(const PatchMesh& mesh, size_t i, const Vec3& d);

/// Fills mesh.texturedReflectance when the scene has textures: each textured patch's mean
/// of ρ over its triangle, from the texels (decoded, not interpolated) at the centroids of
/// a lattice of k² sub-triangles, k = clamp(4 × the patch's longest edge in texels, 4, 64),
/// untextured patches their material's reflectance. Needs scene.textureImages.
void computeTexturedReflectance(const scene::Scene& scene, PatchMesh& mesh);

}  // namespace rayrad::radiosity
