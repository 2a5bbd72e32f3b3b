// Sealed solids: whose surfaces' backs the direct pass may skip.
#include <radiosity/direct/sealed_solids.h>
#include <scene/scene.h>
#include <scene/scene_parser.h>

#include "test_support.h"

#include <algorithm>

using namespace rayrad;

namespace {
scene::Scene sceneWith(const std::string& objects, const std::string& lights) {
    std::string json = R"({"materials": {"m": {"reflectance": 0.5}, "glass": {"type": "glass"}},
        "objects": [)" +
                       objects + R"(], "lights": [)" + lights + "]}";
    return scene::buildScene(scene::parseScene(json, "t.json"));
}
const std::string kLightAbove = R"({"type": "point", "position": [0.5, 0.5, 3], "intensity_cd": 100})";
const std::string kBox = R"({"type": "box", "material": "m", "min": [0, 0, 0], "max": [1, 1, 1]})";
/// The box's faces as quads (counter-clockwise from outside), the last `drop` left out.
std::string boxQuads(int drop = 0, bool flipTop = false) {
    const char* faces[6] = {"[[0,0,0],[0,1,0],[1,1,0],[1,0,0]]", "[[0,0,1],[1,0,1],[1,1,1],[0,1,1]]",
                            "[[0,0,0],[1,0,0],[1,0,1],[0,0,1]]", "[[0,1,0],[0,1,1],[1,1,1],[1,1,0]]",
                            "[[0,0,0],[0,0,1],[0,1,1],[0,1,0]]", "[[1,0,0],[1,1,0],[1,1,1],[1,0,1]]"};
    std::string out;
    for (int k = 0; k < 6 - drop; ++k) {
        std::string v = faces[k];
        if (flipTop && k == 1) v = "[[0,0,1],[0,1,1],[1,1,1],[1,0,1]]";
        out += std::string(out.empty() ? "" : ", ") + R"({"type": "quad", "material": "m", "vertices": )" + v + "}";
    }
    return out;
}
bool all(const std::vector<char>& v) {
    return !v.empty() && std::all_of(v.begin(), v.end(), [](char c) { return c != 0; });
}
bool none(const std::vector<char>& v) {
    return std::none_of(v.begin(), v.end(), [](char c) { return c != 0; });
}
}  // namespace

TEST_CASE("sealed solids: a closed box with the light outside, and what is not one", "[direct]") {
    // A box object and the same box of six quads (six groups welded by position): sealed.
    CHECK(all(radiosity::sealedGroups(sceneWith(kBox, kLightAbove))));
    CHECK(all(radiosity::sealedGroups(sceneWith(boxQuads(), kLightAbove))));
    // A lamp inside lights the backs.
    CHECK(none(radiosity::sealedGroups(
        sceneWith(kBox, R"({"type": "point", "position": [0.5, 0.5, 0.5], "intensity_cd": 1})"))));
    // An open box (no lid), a lid wound the wrong way, a glass lid: not sealed.
    CHECK(none(radiosity::sealedGroups(sceneWith(boxQuads(1), kLightAbove))));
    CHECK(none(radiosity::sealedGroups(sceneWith(boxQuads(0, true), kLightAbove))));
    const std::string glassLid =
        boxQuads(1) + R"(, {"type": "quad", "material": "glass", "vertices": [[0,0,1],[1,0,1],[1,1,1],[0,1,1]]})";
    CHECK(none(radiosity::sealedGroups(sceneWith(glassLid, kLightAbove))));
    // Two boxes: the one with the lamp inside keeps its backs, the other is sealed.
    const auto two = radiosity::sealedGroups(
        sceneWith(kBox + R"(, {"type": "box", "material": "m", "min": [3, 0, 0], "max": [4, 1, 1]})",
                  R"({"type": "point", "position": [3.5, 0.5, 0.5], "intensity_cd": 1})"));
    REQUIRE(two.size() == 12);
    CHECK(all(std::vector<char>(two.begin(), two.begin() + 6)));
    CHECK(none(std::vector<char>(two.begin() + 6, two.end())));
}
