// Rays traced together (Embree packets) give the answers single rays give. Embree's packet
// and single-ray kernels are not bit for bit the same: a ray from a point on the mesh's
// edges that grazes a surface within float precision may be decided either way (the
// office: 8 of ~66 000 such rays). From inside a patch, as the solver's rays leave, they
// must agree.
#include <app/pipeline.h>
#include <radiosity/mesh/mesher.h>
#include <raytrace/embree_scene.h>

#include "test_support.h"

#include <filesystem>
#include <random>

using namespace rayrad;

namespace {

struct Mismatches {
    int fromInside = 0, fromEdges = 0, raysFromEdges = 0;
};

/// From patch centroids and corners toward other patches' centroids and random points on
/// them, in groups of 1 … 19 targets: every answer of visibleFromSurfaceMany against
/// visibleFromSurface.
Mismatches mismatches(const std::string& sceneFile, int points) {
    const scene::Scene scene = app::loadSceneFile(sceneFile, {});
    const radiosity::PatchMesh mesh = radiosity::premesh(scene, scene.meshing);
    const auto embree = raytrace::buildEmbreeScene(scene, mesh);
    std::mt19937 rng(7);
    std::uniform_int_distribution<size_t> patch(0, mesh.patches.size() - 1);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Mismatches wrong;
    for (int k = 0; k < points; ++k) {
        const radiosity::Patch& at = mesh.patches[patch(rng)];
        // From the centroid, or from a corner (on the mesh's edges: grazing rays).
        const bool onEdge = k % 3 == 2;
        const Vec3 from = onEdge ? mesh.vertices[at.v[(k / 3) % 3]] : at.centroid;
        // Targets near one another (a member group) or anywhere, one count per point.
        const radiosity::Patch& around = mesh.patches[patch(rng)];
        const size_t count = 1 + k % 19;
        std::vector<Vec3> targets;
        for (size_t t = 0; t < count; ++t) {
            const radiosity::Patch& p = k % 2 ? mesh.patches[patch(rng)] : around;
            const double a = u(rng), b = u(rng) * (1 - a);
            const Vec3 corner[3] = {mesh.vertices[p.v[0]], mesh.vertices[p.v[1]], mesh.vertices[p.v[2]]};
            targets.push_back(t == 0 ? p.centroid
                                     : corner[0] + a * (corner[1] - corner[0]) + b * (corner[2] - corner[0]));
        }
        bool together[19];
        embree->visibleFromSurfaceMany(from, at.normal, targets.data(), count, together);
        for (size_t t = 0; t < count; ++t) {
            const bool differs = together[t] != embree->visibleFromSurface(from, at.normal, targets[t]);
            (onEdge ? wrong.fromEdges : wrong.fromInside) += differs;
            wrong.raysFromEdges += onEdge;
        }
    }
    return wrong;
}

}  // namespace

TEST_CASE("rays traced together answer as single rays do (office: furniture on the floor, touching boxes)",
          "[visibility]") {
    const Mismatches m = mismatches(test::sourcePath("scenes/office/office.json"), 20000);
    CHECK(m.fromInside == 0);
    CHECK(m.fromEdges <= m.raysFromEdges / 1000);
}

TEST_CASE("rays traced together answer as single rays do (the living room: an imported mesh)", "[visibility]") {
    const std::string file = test::sourcePath("scenes/living-room/living-room.json");
    REQUIRE(std::filesystem::exists(file));
    const Mismatches m = mismatches(file, 20000);
    CHECK(m.fromInside == 0);
    CHECK(m.fromEdges <= m.raysFromEdges / 1000);
}
