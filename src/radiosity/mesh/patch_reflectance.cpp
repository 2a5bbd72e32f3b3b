#include <radiosity/mesh/patch_reflectance.h>

#include <core/check.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace rayrad::radiosity {

namespace {

/// The material's multiplier times a texture value, each channel clamped to kMaxFileReflectance.
Rgb clampedProduct(const Rgb& reflectance, const Rgb& texture) {
    Rgb rho = reflectance * texture;
    for (int c = 0; c < 3; ++c) rho[c] = std::clamp(rho[c], 0.0, scene::kMaxFileReflectance);
    return rho;
}

glm::dvec2 uvAt(const PatchMesh& mesh, size_t i, double u, double v) {
    return (1 - u - v) * glm::dvec2(mesh.cornerUv[3 * i]) + u * glm::dvec2(mesh.cornerUv[3 * i + 1]) +
           v * glm::dvec2(mesh.cornerUv[3 * i + 2]);
}

/// ρ at (u, v) of a textured patch from the texel there (no interpolation).
Rgb texelAt(const scene::Scene& scene, const PatchMesh& mesh, size_t i, double u, double v) {
    const scene::Material& m = scene.materials[mesh.patches[i].material];
    const glm::dvec2 uv = uvAt(mesh, i, u, v);
    return clampedProduct(m.reflectance, scene.textureImages->texel(m.texture, uv.x, uv.y));
}

}  // namespace

glm::dvec2 textureChange(const PatchMesh& mesh, size_t i, const Vec3& d) {
    const Patch& p = mesh.patches[i];
    const Vec3 e1 = mesh.corner(p, 1) - mesh.corner(p, 0), e2 = mesh.corner(p, 2) - mesh.corner(p, 0);
    const glm::dvec2 t1 = glm::dvec2(mesh.cornerUv[3 * i + 1]) - glm::dvec2(mesh.cornerUv[3 * i]);
    const glm::dvec2 t2 = glm::dvec2(mesh.cornerUv[3 * i + 2]) - glm::dvec2(mesh.cornerUv[3 * i]);
    // [e1·e1 e1·e2; e1·e2 e2·e2] (α, β) = (e1·d, e2·d).
    const double a = glm::dot(e1, e1), b = glm::dot(e1, e2), c = glm::dot(e2, e2);
    const double det = a * c - b * b;
    if (!(det > 0)) return glm::dvec2(0.0);  // a degenerate patch: no footprint
    const double r1 = glm::dot(e1, d), r2 = glm::dot(e2, d);
    const double alpha = (c * r1 - b * r2) / det, beta = (a * r2 - b * r1) / det;
    return alpha * t1 + beta * t2;
}

Rgb reflectanceAt(const scene::Scene& scene, const PatchMesh& mesh, size_t i, double u, double v,
                  const Vec3& footprintA, const Vec3& footprintB) {
    const scene::Material& m = scene.materials[mesh.patches[i].material];
    if (m.texture < 0 || mesh.cornerUv.empty() || !scene.textureImages) return m.reflectance;
    const glm::dvec2 uv = uvAt(mesh, i, u, v);
    return clampedProduct(m.reflectance,
                          scene.textureImages->lookup(m.texture, uv.x, uv.y, textureChange(mesh, i, footprintA),
                                                      textureChange(mesh, i, footprintB)));
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
            longest = std::max(longest, static_cast<double>(glm::length(mesh.cornerUv[3 * i + k] -
                                                                        mesh.cornerUv[3 * i + (k + 1) % 3])));
        const int n =
            std::clamp(static_cast<int>(std::ceil(4 * longest * scene.textureImages->resolution(m.texture))), 4, 64);
        // Centroids of the n² sub-triangles of the lattice: the up ones (i, j), (i+1, j),
        // (i, j+1) and the down ones (i+1, j), (i+1, j+1), (i, j+1), in units of 1/n.
        Rgb sum(0.0);
        for (int b = 0; b < n; ++b)
            for (int a = 0; a + b < n; ++a) {
                sum += texelAt(scene, mesh, i, (a + 1.0 / 3) / n, (b + 1.0 / 3) / n);
                if (a + b + 1 < n) sum += texelAt(scene, mesh, i, (a + 2.0 / 3) / n, (b + 2.0 / 3) / n);
            }
        mesh.texturedReflectance[i] = RgbF(sum / static_cast<double>(n * n));
    });
}

}  // namespace rayrad::radiosity
