#include <radiosity/patch_reflectance.h>

#include <core/check.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace rayrad::radiosity {

namespace {

/// ρ at (u, v) of a textured patch: the material's multiplier times the texture (bilinear,
/// or the texel there), each channel clamped to kMaxFileReflectance.
Rgb texturedAt(const scene::Scene& scene, const PatchMesh& mesh, size_t i, double u, double v, bool bilinear) {
    const scene::Material& m = scene.materials[mesh.patches[i].material];
    const glm::dvec2 uv = (1 - u - v) * glm::dvec2(mesh.cornerUv[3 * i]) + u * glm::dvec2(mesh.cornerUv[3 * i + 1]) +
                          v * glm::dvec2(mesh.cornerUv[3 * i + 2]);
    const TextureSource& images = *scene.textureImages;
    Rgb rho = m.reflectance * (bilinear ? images.lookup(m.texture, uv.x, uv.y) : images.texel(m.texture, uv.x, uv.y));
    for (int c = 0; c < 3; ++c) rho[c] = std::clamp(rho[c], 0.0, scene::kMaxFileReflectance);
    return rho;
}

}  // namespace

Rgb reflectanceAt(const scene::Scene& scene, const PatchMesh& mesh, size_t i, double u, double v) {
    const scene::Material& m = scene.materials[mesh.patches[i].material];
    if (m.texture < 0 || mesh.cornerUv.empty() || !scene.textureImages) return m.reflectance;
    return texturedAt(scene, mesh, i, u, v, true);
}

void computeTexturedReflectance(const scene::Scene& scene, PatchMesh& mesh) {
    mesh.texturedReflectance.clear();
    if (scene.textures.empty()) return;
    CHECK(scene.textureImages != nullptr);
    CHECK(mesh.cornerUv.size() == 3 * mesh.patches.size());
    mesh.texturedReflectance.resize(mesh.patches.size());
    tbb::parallel_for(size_t(0), mesh.patches.size(), [&](size_t i) {
        const scene::Material& m = scene.materials[mesh.patches[i].material];
        if (m.texture < 0) {
            mesh.texturedReflectance[i] = RgbF(m.reflectance);
            return;
        }
        // The longest edge in texels decides the lattice.
        double longest = 0;
        for (int k = 0; k < 3; ++k)
            longest = std::max(longest, static_cast<double>(glm::length(mesh.cornerUv[3 * i + k] - mesh.cornerUv[3 * i + (k + 1) % 3])));
        const int n = std::clamp(static_cast<int>(std::ceil(4 * longest * scene.textureImages->resolution(m.texture))), 4, 64);
        // Centroids of the n² sub-triangles of the lattice: the up ones (i, j), (i+1, j),
        // (i, j+1) and the down ones (i+1, j), (i+1, j+1), (i, j+1), in units of 1/n.
        Rgb sum(0.0);
        for (int b = 0; b < n; ++b)
            for (int a = 0; a + b < n; ++a) {
                sum += texturedAt(scene, mesh, i, (a + 1.0 / 3) / n, (b + 1.0 / 3) / n, false);
                if (a + b + 1 < n) sum += texturedAt(scene, mesh, i, (a + 2.0 / 3) / n, (b + 2.0 / 3) / n, false);
            }
        mesh.texturedReflectance[i] = RgbF(sum / static_cast<double>(n * n));
    });
}

}  // namespace rayrad::radiosity
