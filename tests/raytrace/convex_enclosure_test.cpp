// A scene that is one convex enclosure traces no shadow rays between points inside it;
// anything else, and any segment leaving it, is still traced.
#include <app/pipeline.h>
#include <radiosity/mesh/mesher.h>
#include <raytrace/convex_enclosure.h>
#include <raytrace/embree_scene.h>

#include "test_support.h"

using namespace rayrad;

namespace {

struct Triangles {
    std::vector<std::array<Vec3, 3>> corners;
    std::vector<Vec3> normals;
    void add(const Vec3& a, const Vec3& b, const Vec3& c) {
        corners.push_back({a, b, c});
        normals.push_back(glm::normalize(glm::cross(b - a, c - a)));
    }
    /// The quad a b c d (counter-clockwise seen from its front) as two triangles.
    void quad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) { add(a, b, c), add(a, c, d); }
};

/// The faces of the box [lo, hi], fronts facing in (a room) or out (a block); without its top when `open`.
Triangles box(const Vec3& lo, const Vec3& hi, bool facingIn, bool open = false) {
    Triangles t;
    auto quad = [&](Vec3 a, Vec3 b, Vec3 c, Vec3 d) { facingIn ? t.quad(a, b, c, d) : t.quad(d, c, b, a); };
    const double x0 = lo.x, y0 = lo.y, z0 = lo.z, x1 = hi.x, y1 = hi.y, z1 = hi.z;
    quad({x0, y0, z0}, {x1, y0, z0}, {x1, y1, z0}, {x0, y1, z0});  // floor, up
    if (!open) quad({x0, y0, z1}, {x0, y1, z1}, {x1, y1, z1}, {x1, y0, z1});  // ceiling, down
    quad({x0, y0, z0}, {x0, y1, z0}, {x0, y1, z1}, {x0, y0, z1});  // x = x0, toward +x
    quad({x1, y0, z0}, {x1, y0, z1}, {x1, y1, z1}, {x1, y1, z0});  // x = x1, toward −x
    quad({x0, y0, z0}, {x0, y0, z1}, {x1, y0, z1}, {x1, y0, z0});  // y = y0, toward +y
    quad({x0, y1, z0}, {x1, y1, z0}, {x1, y1, z1}, {x0, y1, z1});  // y = y1, toward −y
    return t;
}

}  // namespace

TEST_CASE("convex enclosure: an empty room is one, a room with a block or a face turned out is not") {
    const double tol = 1e-9;
    Triangles room = box({0, 0, 0}, {4, 3, 2.5}, true);
    REQUIRE(glm::dot(room.normals[0], Vec3(0, 0, 1)) > 0.99);  // the floor faces up, into the room
    const raytrace::ConvexEnclosure empty(room.corners, room.normals, tol);
    CHECK(empty.planeCount() == 6);
    CHECK(empty.contains({2, 1.5, 1}));
    CHECK(empty.contains({0, 1.5, 1}));    // on a wall
    CHECK(empty.contains({4, 3, 2.5}));    // a corner
    CHECK_FALSE(empty.contains({2, 1.5, 2.6}));  // above the ceiling
    CHECK_FALSE(empty.contains({-1e-6, 1, 1}));  // just behind a wall

    Triangles furnished = room;
    const Triangles block = box({1, 1, 0}, {2, 2, 0.8}, false);
    furnished.corners.insert(furnished.corners.end(), block.corners.begin(), block.corners.end());
    furnished.normals.insert(furnished.normals.end(), block.normals.begin(), block.normals.end());
    CHECK(raytrace::ConvexEnclosure(furnished.corners, furnished.normals, tol).empty());

    Triangles turned = room;
    for (int k : {0, 1}) turned.normals[k] = -turned.normals[k];  // the floor faces down
    CHECK(raytrace::ConvexEnclosure(turned.corners, turned.normals, tol).empty());

    // Without its ceiling: the set above the walls' feet, between their planes.
    const Triangles open = box({0, 0, 0}, {4, 3, 2.5}, true, true);
    const raytrace::ConvexEnclosure roofless(open.corners, open.normals, tol);
    CHECK(roofless.planeCount() == 5);
    CHECK(roofless.contains({2, 1.5, 10}));
    CHECK_FALSE(roofless.contains({5, 1.5, 1}));
}

TEST_CASE("convex enclosure: the cube traces no rays inside, and still those that leave it") {
    const scene::Scene cube = app::loadSceneFile(test::sourcePath("scenes/cube/cube.json"), {scene::parseOverride("radiosity.max_edge=1")});
    const radiosity::PatchMesh mesh = radiosity::premesh(cube, cube.meshing);
    const auto embree = raytrace::buildEmbreeScene(cube, mesh);
    REQUIRE(embree->convexEnclosure().planeCount() == 6);
    const Vec3 floor(5, 5, 0), up(0, 0, 1);
    CHECK(embree->visibleFromSurface(floor, up, {0, 0, 10}));      // the ceiling's corner
    CHECK_FALSE(embree->visibleFromSurface(floor, up, {5, 5, 11}));  // above the ceiling: it blocks
    bool many[2];
    const Vec3 targets[2] = {Vec3(10, 3, 7), Vec3(11, 3, 7)};
    embree->visibleFromSurfaceMany(floor, up, targets, 2, many);
    CHECK(many[0]);
    CHECK_FALSE(many[1]);  // beyond a wall

    // A box in a room is no enclosure: its rays are traced.
    const scene::Scene cornell = app::loadSceneFile(test::sourcePath("scenes/cornell/cornell.json"), {});
    const radiosity::PatchMesh cornellMesh = radiosity::premesh(cornell, cornell.meshing);
    CHECK(raytrace::buildEmbreeScene(cornell, cornellMesh)->convexEnclosure().empty());
}
