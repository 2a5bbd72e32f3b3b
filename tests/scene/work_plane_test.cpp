// Work planes: horizontal grids over a room outline with a border and the
// EN 12464-1 spacing.
#include <scene/scene_parser.h>

#include <catch2/catch.hpp>

using namespace rayrad;
using namespace rayrad::scene;

TEST_CASE("a work plane: EN 12464-1 spacing over a room outline, a border, an L-shaped room", "[scene][grids]") {
    auto points = [](const std::string& plane) {
        const std::string json = R"({"materials": {"w": {"reflectance": 0.5}},
            "objects": [{"type": "box", "min": [0, 0, 0], "max": [10, 3, 10], "facing": "inward", "material": "w"}],
            "lights": [{"type": "point", "position": [5, 2.5, 5], "intensity_cd": 100}],
            "work_planes": [)" + plane + "]}";
        return parseScene(json, "wp.json").sensors;
    };
    // p = 0.2 · 5^log10(d): 10 m → 1 m, so 10 × 10 points at the cell centres.
    const auto ten = points(R"({"name": "a", "outline": [[0, 0], [10, 0], [10, 10], [0, 10]], "height": 0.75, "border": 0})");
    REQUIRE(ten.size() == 100);
    CHECK(ten[0].position == Vec3(0.5, 0.75, 0.5));
    CHECK(ten[0].grid == "a");
    CHECK(ten[0].normal == Vec3(0, 1, 0));
    // 1 m → 0.2 m: 5 × 5 points.
    CHECK(points(R"({"name": "b", "outline": [[2, 2], [3, 2], [3, 3], [2, 3]], "border": 0})").size() == 25);
    // A 0.5 m border around a 4 m room leaves 3 m: p = 0.431 m, 7 × 7 points.
    CHECK(points(R"({"name": "c", "outline": [[0, 0], [4, 0], [4, 4], [0, 4]], "border": 0.5})").size() == 49);
    // An L: the points of the missing quarter, and those within the border of the inner corner, are left out.
    const auto l = points(R"({"name": "L", "outline": [[0, 0], [4, 0], [4, 2], [2, 2], [2, 4], [0, 4]], "border": 0.25, "spacing": 0.5})");
    CHECK(l.size() == 33);
    for (const auto& s : l) CHECK_FALSE((s.position.x > 2 && s.position.z > 2));
    CHECK_THROWS_WITH(points(R"({"outline": [[0, 0], [4, 0]]})"),
                      Catch::Contains("/work_planes/0/outline: expected at least three corners enclosing an area"));
}
