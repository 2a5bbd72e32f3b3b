// The ray cone's footprint on a surface and its texture-space axes (textures
// filtered over what a pixel sample covers).
#include <radiosity/mesh/patch_reflectance.h>
#include <raytrace/ray_cone.h>

#include "test_support.h"

#include <cmath>

using namespace rayrad;

TEST_CASE("a ray cone's footprint: w across, w / cos θ along the surface", "[raytrace]") {
    const raytrace::RayCone cone{0.01, 0.002};
    CHECK(cone.widthAt(10) == Approx(0.03));
    CHECK(cone.continuedAt(5).widthAt(5) == Approx(0.03));  // through a flat mirror: as if straight on
    const Vec3 n(0, 1, 0);
    const auto [headOnA, headOnB] = raytrace::surfaceFootprint(0.03, Vec3(0, -1, 0), n);
    CHECK(glm::length(headOnA) == Approx(0.03));
    CHECK(glm::length(headOnB) == Approx(0.03));
    CHECK(glm::dot(headOnA, n) == Approx(0.0).margin(1e-12));
    // 60° from the normal: stretched twice along the ray's direction on the floor (−z).
    const Vec3 d = glm::normalize(Vec3(0, -std::cos(glm::radians(60.0)), -std::sin(glm::radians(60.0))));
    const auto [along, across] = raytrace::surfaceFootprint(0.03, d, n);
    CHECK(along.z == Approx(-0.06));
    CHECK(std::abs(across.x) == Approx(0.03));
    // Grazing: capped at 32:1.
    const auto [graze, ignored] = raytrace::surfaceFootprint(0.03, glm::normalize(Vec3(0, -1e-6, -1)), n);
    CHECK(glm::length(graze) == Approx(32 * 0.03));
}

TEST_CASE("a world-space displacement on a patch as a change of texture coordinates", "[raytrace]") {
    radiosity::PatchMesh mesh;
    // A 2 × 1 m triangle in the floor plane, mapped to uv (0,0), (4,0), (0,3): 2 repeats per
    // metre along x, 3 along −z.
    mesh.vertices = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 0, -1)};
    radiosity::Patch p;
    p.v[0] = 0, p.v[1] = 1, p.v[2] = 2;
    mesh.patches.push_back(p);
    mesh.cornerUv = {glm::vec2(0, 0), glm::vec2(4, 0), glm::vec2(0, 3)};
    const glm::dvec2 dx = radiosity::textureChange(mesh, 0, Vec3(0.1, 0, 0));
    CHECK(dx.x == Approx(0.2));
    CHECK(dx.y == Approx(0.0).margin(1e-12));
    const glm::dvec2 dz = radiosity::textureChange(mesh, 0, Vec3(0, 0, -0.1));
    CHECK(dz.x == Approx(0.0).margin(1e-12));
    CHECK(dz.y == Approx(0.3));
}
