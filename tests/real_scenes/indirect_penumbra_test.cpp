// The indirect light in the shadow of an object: a part of a shooting cluster far from a
// receiver sends as one source, and its visibility must not hang on one ray.
#include "../radiosity/solved_scene.h"
#include "test_support.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace rayrad;

TEST_CASE("shooting: the floor beside a block reads the light a far source sends past the block", "[real_scenes]") {
    // The tutorial room (tinyobjloader's Cornell OBJ) at 0.1 m patches: the floor beside the
    // short block, from 5 mm to 8 cm out from its side, sees the bright ceiling around the
    // lamp partly past the block. One ray toward a far node's brightest member hid the
    // whole node there, and the solve read 35 % below the gather over the first 12 cm.
    // Points out from the block's side, the edge from (1.30, 0.65) to (2.90, 1.14) m.
    const double ex = 2.549, ez = 1.0325, nx = 0.293, nz = -0.956;
    std::string sensors = "[";
    for (double d : {0.005, 0.02, 0.05, 0.08})
        sensors += (sensors.size() > 1 ? "," : "") + std::string(R"({"name": "d)") + std::to_string(d) +
                   R"(", "position": [)" + std::to_string(ex + nx * d) + ", 0, " + std::to_string(ez + nz * d) +
                   R"(], "normal": [0, 1, 0]})";
    sensors += "]";
    const auto s = test::solve(test::sourcePath("scenes/tutorial/room.json"),
                               {{"radiosity.max_edge", "0.1"}, {"sensors", sensors}, {"work_planes", "[]"}});
    REQUIRE(s.sensors.size() == 4);
    for (const auto& r : s.sensors) {
        REQUIRE(r.value.indirectVertex);
        const double mesh = luminance(*r.value.indirectVertex), gathered = luminance(r.value.indirect);
        INFO(r.sensor.name << ": mesh " << mesh << " lx, gathered " << gathered << " lx");
        CHECK(gathered > 100);
        CHECK(std::abs(mesh - gathered) < 0.06 * gathered);
    }
}
