// Creases in mesh files: a box whose faces share their corner vertices (as importers join
// identical positions) gets one vertex per face at each corner, so its display values do
// not average the light of its top into its sides.
#include <radiosity/mesh/crease_split.h>

#include "solved_scene.h"
#include "test_support.h"

#include <catch2/catch.hpp>

#include <fstream>
#include <set>

using namespace rayrad;

namespace {

/// A unit cube's 8 corners and 12 outward triangles, every corner shared by three faces.
void weldedCube(std::vector<Vec3>& positions, std::vector<std::array<uint32_t, 3>>& triangles) {
    positions.clear();
    for (int i = 0; i < 8; ++i) positions.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    // Quads CCW seen from outside: -x, +x, -y, +y, -z, +z.
    const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    triangles.clear();
    for (const auto& q : quads) {
        triangles.push_back({uint32_t(q[0]), uint32_t(q[1]), uint32_t(q[2])});
        triangles.push_back({uint32_t(q[0]), uint32_t(q[2]), uint32_t(q[3])});
    }
}

}  // namespace

TEST_CASE("creases: a welded cube's corners become one vertex per face", "[mesher]") {
    std::vector<Vec3> positions;
    std::vector<std::array<uint32_t, 3>> triangles;
    weldedCube(positions, triangles);
    CHECK(radiosity::splitAtCreases(positions, triangles, 40) == 16);  // 8 corners × 3 faces = 24
    REQUIRE(positions.size() == 24);
    // No vertex is shared by triangles of different normals, and the two triangles of a
    // face still share their diagonal.
    std::map<uint32_t, std::set<std::tuple<double, double, double>>> normalsAt;
    for (const auto& t : triangles) {
        const Vec3 n = glm::normalize(glm::cross(positions[t[1]] - positions[t[0]], positions[t[2]] - positions[t[0]]));
        for (uint32_t v : t) normalsAt[v].insert({std::round(n.x), std::round(n.y), std::round(n.z)});
    }
    for (const auto& [v, normals] : normalsAt) CHECK(normals.size() == 1);
    CHECK(normalsAt.size() == 24);

    // 0 splits nothing; so does any angle above the crease.
    weldedCube(positions, triangles);
    CHECK(radiosity::splitAtCreases(positions, triangles, 0) == 0);
    CHECK(radiosity::splitAtCreases(positions, triangles, 95) == 0);
}

TEST_CASE("creases: a flat fan and a finely faceted curve keep their shared vertices", "[mesher]") {
    // A hexagonal fan in a plane.
    std::vector<Vec3> positions{Vec3(0.0)};
    std::vector<std::array<uint32_t, 3>> triangles;
    for (int k = 0; k < 6; ++k) positions.emplace_back(std::cos(k * kPi / 3), std::sin(k * kPi / 3), 0);
    for (uint32_t k = 0; k < 6; ++k) triangles.push_back({0, 1 + k, 1 + (k + 1) % 6});
    CHECK(radiosity::splitAtCreases(positions, triangles, 40) == 0);
    // A 12-sided cylinder wall: 30° between neighbouring facets.
    positions.clear();
    triangles.clear();
    for (int k = 0; k < 12; ++k) {
        positions.emplace_back(std::cos(k * kPi / 6), std::sin(k * kPi / 6), 0);
        positions.emplace_back(std::cos(k * kPi / 6), std::sin(k * kPi / 6), 1);
    }
    for (uint32_t k = 0; k < 12; ++k) {
        const uint32_t a = 2 * k, b = 2 * ((k + 1) % 12);
        triangles.push_back({a, b, b + 1});
        triangles.push_back({a, b + 1, a + 1});
    }
    CHECK(radiosity::splitAtCreases(positions, triangles, 40) == 0);
    CHECK(radiosity::splitAtCreases(positions, triangles, 20) > 0);
}

TEST_CASE("creases: the side of a welded box agrees with the gather up to its top edge", "[mesher]") {
    // A 1 m cube standing in a 4 × 3 × 4 m room, a spot above it lighting the ceiling: the
    // cube's top sees the bright ceiling face on, its sides at a graze (the top's indirect
    // light is twice theirs). A side's vertex values just below the top edge must be its own
    // light, not the average with the top's.
    const std::string obj = "/tmp/rayrad_test_welded_box.obj";
    {
        std::ofstream out(obj);
        for (int i = 0; i < 8; ++i)
            out << "v " << 1.5 + (i & 1) << ' ' << ((i >> 1) & 1) << ' ' << 1.5 + ((i >> 2) & 1) << '\n';
        out << "f 1 5 7 3\nf 2 4 8 6\nf 1 2 6 5\nf 3 7 8 4\nf 1 3 4 2\nf 5 6 8 7\n";
    }
    auto quad = [](const char* v) {
        return std::string(R"({"type": "quad", "material": "wall", "vertices": )") + v + "}";
    };
    const std::string json =
        R"({"materials": {"wall": {"reflectance": 0.6}, "box": {"reflectance": 0.6}},
        "objects": [)" +
        quad("[[0,0,0],[0,0,4],[4,0,4],[4,0,0]]") + "," + quad("[[0,3,0],[4,3,0],[4,3,4],[0,3,4]]") + "," +
        quad("[[0,0,0],[4,0,0],[4,3,0],[0,3,0]]") + "," + quad("[[0,0,4],[0,3,4],[4,3,4],[4,0,4]]") + "," +
        quad("[[0,0,0],[0,3,0],[0,3,4],[0,0,4]]") + "," + quad("[[4,0,0],[4,0,4],[4,3,4],[4,3,0]]") +
        R"(, {"type": "mesh", "file": ")" + obj + R"(", "material": "box"}],
        "lights": [{"type": "spot", "position": [2, 2.5, 2], "look_at": [2, 3, 2], "intensity_cd": 1000,
                    "inner_angle_deg": 50, "outer_angle_deg": 60}],
        "sensors": [{"name": "top", "position": [2.5, 0.98, 2.5], "normal": [0, 0, 1]},
                    {"name": "middle", "position": [2.5, 0.5, 2.5], "normal": [0, 0, 1]}],
        "radiosity": {"max_edge": 0.25}})";
    auto relativeDifference = [](const test::SolvedScene& s, size_t k) {
        const auto& v = s.sensors.at(k).value;
        REQUIRE(v.indirectVertex);
        return std::abs(luminance(*v.indirectVertex) - luminance(v.indirect)) / luminance(v.indirect);
    };
    const auto split = test::solve(test::writeTempScene("welded_box", json));
    REQUIRE(split.sensors.size() == 2);
    CHECK(relativeDifference(split, 0) < 0.05);
    CHECK(relativeDifference(split, 1) < 0.05);
    // Welded as the file has it, the top edge's vertices average in the top's light (+99 %).
    const auto welded = test::solve(test::writeTempScene("welded_box", json), {{"radiosity.crease_angle_deg", "0"}});
    CHECK(relativeDifference(welded, 0) > 0.3);
}
