// Shared corners: the direct pass evaluates a vertex once for all its patches only where
// that is one point for all of them.
#include <radiosity/direct/shared_corners.h>
#include "solved_scene.h"

#include "test_support.h"

#include <map>

using namespace rayrad;

TEST_CASE("shared corners: inside a flat surface only, never along a wall's foot, a rim or a curved mesh", "[direct]") {
    // A 4 m floor meshed at 1 m with a 1 m box standing on it (its foot cuts the floor's
    // grid: contact lines, vertices made once per side), and a sphere above.
    const std::string scene = R"({"materials": {"m": {"reflectance": 0.5}},
        "objects": [
          {"type": "quad", "material": "m", "vertices": [[0,0,0],[0,0,4],[4,0,4],[4,0,0]]},
          {"type": "box", "material": "m", "min": [1.3, 0, 1.45], "max": [2.3, 1, 2.45]},
          {"type": "sphere", "material": "m", "center": [3, 2, 3], "radius": 0.3, "subdivisions": 2}],
        "lights": [{"type": "point", "position": [2, 3, 3], "intensity_cd": 100}],
        "radiosity": {"max_edge": 1}})";
    const auto run = test::solve(test::writeTempScene("shared_corners", scene));
    const auto& mesh = run.mesh;
    const std::vector<char> shared = radiosity::sharedCorners(mesh);

    auto onFloor = [](const Vec3& v) { return std::abs(v.y) < 1e-9; };
    auto onFoot = [](const Vec3& v) {  // on the outline of the box's foot
        const bool inX = v.x > 1.3 - 1e-9 && v.x<2.3 + 1e-9, inZ = v.z> 1.45 - 1e-9 && v.z < 2.45 + 1e-9;
        const bool edgeX = std::abs(v.x - 1.3) < 1e-9 || std::abs(v.x - 2.3) < 1e-9;
        const bool edgeZ = std::abs(v.z - 1.45) < 1e-9 || std::abs(v.z - 2.45) < 1e-9;
        return (edgeX && inZ) || (edgeZ && inX);
    };
    auto onRim = [](const Vec3& v) {
        return std::abs(v.x) < 1e-9 || std::abs(v.x - 4) < 1e-9 || std::abs(v.z) < 1e-9 || std::abs(v.z - 4) < 1e-9;
    };
    int floorInterior = 0, floorShared = 0, footShared = 0, rimShared = 0, sphereShared = 0, foot = 0;
    for (uint32_t v = 0; v < mesh.vertices.size(); ++v) {
        const Vec3& x = mesh.vertices[v];
        if (glm::length(x - Vec3(3, 2, 3)) < 0.31) {
            sphereShared += shared[v];
        } else if (onFloor(x) && onFoot(x)) {
            ++foot;
            footShared += shared[v];
        } else if (onFloor(x) && onRim(x)) {
            rimShared += shared[v];
        } else if (onFloor(x)) {
            ++floorInterior;
            floorShared += shared[v];
        }
    }
    CHECK(foot > 0);
    CHECK(footShared == 0);  // a corner there would cast shadow rays from inside the box's side
    CHECK(rimShared == 0);
    CHECK(sphereShared == 0);  // each patch has its own normal there
    CHECK(floorInterior > 0);
    CHECK(floorShared == floorInterior);

    // A shared corner has one value for all its patches: lit beyond the box (the light
    // stands at z = 3, the box's shadow falls toward z = 0), dark under it.
    std::map<uint32_t, RgbF> valueAt;
    int sharedCornersSeen = 0;
    for (size_t i = 0; i < mesh.patches.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = mesh.patches[i].v[k];
            if (!shared[v]) continue;
            ++sharedCornersSeen;
            const RgbF e = run.lighting.solution.directCorner[3 * i + k];
            const Vec3& x = mesh.vertices[v];
            if (x.x > 1.3 && x.x < 2.3 && x.z > 1.45 && x.z < 2.45) CHECK(e.g == 0);
            if (x.z > 2.5) CHECK(e.g > 0);
            auto [it, added] = valueAt.emplace(v, e);
            if (!added) CHECK(it->second == e);
        }
    CHECK(sharedCornersSeen > static_cast<int>(valueAt.size()));  // shared by several patches
}
