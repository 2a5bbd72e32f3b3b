// A block that floats a little above the floor, as modellers leave them: the Cornell box
// from Cinema 4D's PBRT exporter (bench/corpus/iset-cornell-box), whose short block hangs
// 2.2 mm above the floor. Its front face gets no direct light (the lamp is behind it) and
// most of its light from the floor strip in front of it, a few centimetres away.
#include "../radiosity/solved_scene.h"
#include "test_support.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace rayrad;

namespace {

/// The short block's front face: its bottom edge from (ax, az) to (bx, bz) at y = bottom
/// (m), the floor at y = floor; the face's outward normal is (nz_along, 0, −nx_along).
constexpr double ax = 0.01904180459678173, az = 1.3600093126296997;
constexpr double bx = 0.1771496683359146, bz = 1.312827229499817;
constexpr double floorY = -0.268694;

/// Sensors on the face at fractions t of its width and heights h above the floor (m).
std::string faceSensors(std::initializer_list<double> ts, std::initializer_list<double> hs) {
    const double len = std::hypot(bx - ax, bz - az), ux = (bx - ax) / len, uz = (bz - az) / len;
    std::string out = "[";
    for (double t : ts)
        for (double h : hs) {
            const double x = ax + t * (bx - ax), z = az + t * (bz - az);
            out += (out.size() > 1 ? "," : "") + std::string(R"({"name": "t)") + std::to_string(t) + "_h" +
                   std::to_string(h) + R"(", "position": [)" + std::to_string(x) + ", " + std::to_string(floorY + h) +
                   ", " + std::to_string(z) + R"(], "normal": [)" + std::to_string(uz) + ", 0, " + std::to_string(-ux) +
                   "]}";
        }
    return out + "]";
}

}  // namespace

TEST_CASE("a block floating 2 mm above the floor: its face, lit by the floor in front, agrees with the gather",
          "[real_scenes][corpus]") {
    // The floor cluster in front of the face shot to it as one cluster (the gap kept the two
    // from counting as touching): the mesh read up to 27 % above the gather across the face.
    // (The last centimetre above the gap is not held here: the face's bottom vertices are
    // no seam, and 6 mm above the floor the mesh reads up to 88 % above the gather.)
    const auto s = test::solve(test::sourcePath("bench/corpus/iset-cornell-box/scene.json"),
                               {{"sensors", faceSensors({0.2, 0.35, 0.5, 0.65, 0.8}, {0.05, 0.1})}});
    REQUIRE(s.sensors.size() == 10);
    for (const auto& r : s.sensors) {
        REQUIRE(r.value.indirectVertex);
        const double mesh = luminance(*r.value.indirectVertex), gathered = luminance(r.value.indirect);
        INFO(r.sensor.name << ": mesh " << mesh << " lx, gathered " << gathered << " lx");
        CHECK(luminance(r.value.direct) == 0);
        CHECK(gathered > 5);
        CHECK(std::abs(mesh - gathered) < 0.1 * gathered);
    }
}
