// Premeshing: exact counts for the paper's cube, area conservation, triangle shape.
#include <radiosity/mesh/mesher.h>
#include <scene/scene.h>
#include <scene/scene_parser.h>

#include "scene/scene_test_util.h"
#include "test_support.h"

#include <cmath>
#include <set>

using namespace rayrad;

namespace {

scene::Scene cube(const std::vector<scene::Override>& o) {
    return scene::buildScene(scene::loadScene(test::sourcePath("scenes/cube/cube.json"), o));
}

/// Smallest angle of a triangle, degrees.
double minAngle(const radiosity::PatchMesh& m, const radiosity::Patch& p) {
    double best = 180;
    for (int k = 0; k < 3; ++k) {
        Vec3 a = m.corner(p, (k + 1) % 3) - m.corner(p, k), b = m.corner(p, (k + 2) % 3) - m.corner(p, k);
        best = std::min(best, glm::degrees(std::acos(glm::dot(a, b) / (glm::length(a) * glm::length(b)))));
    }
    return best;
}

}  // namespace

TEST_CASE("the paper's cube meshes into exactly 1200 4800 19200 and 76800 equal triangles", "[mesher]") {
    for (auto [edge, count] : {std::pair{"1", 1200}, {"0.5", 4800}, {"0.25", 19200}, {"0.125", 76800}}) {
        auto s = cube({{"radiosity.max_edge", edge}});
        auto mesh = radiosity::premesh(s, s.meshing);
        CHECK(mesh.patches.size() == static_cast<size_t>(count));
        CHECK(mesh.totalArea() == Approx(600.0).epsilon(1e-12));
        double a0 = mesh.patches[0].area;
        for (const auto& p : mesh.patches) REQUIRE(p.area == Approx(a0).epsilon(1e-9));
    }
}

TEST_CASE("triangles_per_surface gives the same 2n² mesh", "[mesher]") {
    auto s = cube({{"radiosity.triangles_per_surface", "800"}});
    CHECK(radiosity::premesh(s, s.meshing).patches.size() == 4800);
}

TEST_CASE("a sliver quad becomes many compact triangles with area conserved", "[mesher]") {
    std::string json = R"({"materials": {"m": {"reflectance": 0.5}},
        "objects": [{"type": "quad", "material": "m", "vertices": [[0,0,0],[10,0,0],[10,0.1,0],[0,0.1,0]]}],
        "lights": [{"type": "point", "position": [0,0,1], "intensity_cd": 1}],
        "radiosity": {"max_edge": 2}})";
    auto s = scene::buildScene(scene::parseScene(json, "t.json"));
    auto mesh = radiosity::premesh(s, s.meshing);
    CHECK(mesh.totalArea() == Approx(1.0).epsilon(1e-12));
    CHECK(mesh.patches.size() >= 100);
    for (const auto& p : mesh.patches) REQUIRE(minAngle(mesh, p) > 20.0);
}

TEST_CASE("polygons and meshes: uniform k² split keeps shape and shares edge points", "[mesher]") {
    // A closed sphere (12·n² triangles) split further must stay watertight: V − E + F = 2,
    // i.e. V = F/2 + 2 for a closed triangle mesh.
    std::string json = R"({"materials": {"m": {"reflectance": 0.5}},
        "objects": [{"type": "sphere", "material": "m", "radius": 1, "subdivisions": 4, "facing": "inward"}],
        "lights": [{"type": "point", "position": [0,0,0], "intensity_cd": 1}],
        "radiosity": {"max_edge": 0.3}})";
    auto s = scene::buildScene(scene::parseScene(json, "t.json"));
    auto mesh = radiosity::premesh(s, s.meshing);
    size_t f = mesh.patches.size();
    CHECK(f > 12 * 16);
    CHECK(mesh.vertices.size() == f / 2 + 2);
    double minA = 180;
    for (const auto& p : mesh.patches) minA = std::min(minA, minAngle(mesh, p));
    CHECK(minA > 25.0);
    // Inward sphere: every normal points to the centre.
    for (const auto& p : mesh.patches) REQUIRE(glm::dot(p.normal, p.centroid) < 0);
}

TEST_CASE("a non-convex polygon is triangulated without losing area", "[mesher]") {
    std::string json = R"({"materials": {"m": {"reflectance": 0.5}},
        "objects": [{"type": "polygon", "material": "m",
                     "vertices": [[0,0,0],[2,0,0],[2,2,0],[1,1,0],[0,2,0]]}],
        "lights": [{"type": "point", "position": [0,0,1], "intensity_cd": 1}],
        "radiosity": {"max_edge": 0.25}})";
    auto s = scene::buildScene(scene::parseScene(json, "t.json"));
    auto mesh = radiosity::premesh(s, s.meshing);
    CHECK(mesh.totalArea() == Approx(3.0).epsilon(1e-12));
    for (const auto& p : mesh.patches) REQUIRE(p.normal.z == Approx(1.0));
}
