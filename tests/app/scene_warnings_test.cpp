// Warnings for scenes that are probably wrong: each case gets its one
// line, and a sound scene gets none.
#include <app/pipeline.h>
#include <app/scene_warnings.h>
#include <radiosity/mesh/mesher.h>

#include "test_support.h"

#include <string>
#include <vector>

using namespace rayrad;

namespace {

/// The warnings for a 4 × 3 × 4 m room (inward box) with `extra` objects, `lights`,
/// `sensors` and an optional camera.
std::vector<std::string> warningsFor(const std::string& name, const std::string& extra, const std::string& lights,
                                     const std::string& sensors = "", const std::string& camera = "") {
    std::string json =
        R"({"materials": {"wall": {"reflectance": 0.5}, "mirror": {"type": "mirror", "specular_reflectance": 0.9}},
        "objects": [{"type": "box", "material": "wall", "min": [0, 0, 0], "max": [4, 3, 4], "facing": "inward"})" +
        extra + R"(], "lights": [)" + lights + R"(], "sensors": [)" + sensors + "]" + camera + "}";
    auto scene = app::loadSceneFile(test::writeTempScene("warn_" + name, json), {});
    auto mesh = radiosity::premesh(scene, scene.meshing);
    auto embree = raytrace::buildEmbreeScene(scene, mesh);
    return app::sceneWarnings(scene, mesh, *embree);
}

bool mentions(const std::vector<std::string>& warnings, const std::string& fragment) {
    for (const auto& w : warnings)
        if (w.find(fragment) != std::string::npos) return true;
    return false;
}

const char* kLight = R"({"type": "point", "position": [2, 2.5, 2], "intensity_cd": 100})";
const char* kBlock = R"(, {"type": "box", "material": "wall", "min": [1, 0, 1], "max": [2, 1, 2]})";

}  // namespace

TEST_CASE("a sound room gets no warning and sensors on edges and corners are not 'buried'", "[warnings]") {
    auto w = warningsFor("sound", kBlock, kLight,
                         R"({"name": "floor", "position": [3, 0, 3], "normal": [0, 1, 0]},
                            {"name": "edge", "position": [0, 0, 3], "normal": [0, 1, 0]},
                            {"name": "corner", "position": [0, 0, 0], "normal": [0.57735, 0.57735, 0.57735]},
                            {"name": "block foot", "position": [2, 0, 1.5], "normal": [0, 1, 0]})",
                         R"(, "camera": {"position": [3.5, 1.5, 3.5], "look_at": [1, 1, 1]})");
    INFO(w.size() << " warnings, first: " << (w.empty() ? "" : w[0]));
    CHECK(w.empty());
}

TEST_CASE("sensors just off the surface they face are named once, with the farthest", "[warnings]") {
    // The room's diagonal is 6.4 m: within 6.4 mm of a surface facing the same way counts.
    auto w = warningsFor("off_surface", kBlock, kLight,
                         R"({"name": "on", "position": [3, 0, 3], "normal": [0, 1, 0]},
                            {"name": "half a millimetre up", "position": [3, 0.0005, 2], "normal": [0, 1, 0]},
                            {"name": "two millimetres up", "position": [2.5, 0.002, 3], "normal": [0, 1, 0]},
                            {"name": "a work plane", "position": [3, 0.8, 3], "normal": [0, 1, 0]},
                            {"name": "a centimetre off the wall", "position": [0.01, 1.5, 3], "normal": [1, 0, 0]})");
    INFO(w.size() << " warnings, first: " << (w.empty() ? "" : w[0]));
    REQUIRE(w.size() == 1);
    CHECK(mentions(w,
                   "/sensors: 2 sensor(s) lie just off the surface they face, not on it (\"two millimetres up\" at "
                   "(2.5, 0.002, 3): 2 mm off)"));
}

TEST_CASE("a light, camera or sensor inside a solid is named", "[warnings]") {
    auto w =
        warningsFor("inside", kBlock,
                    R"({"type": "point", "position": [1.5, 0.5, 1.5], "intensity_cd": 100}, )" + std::string(kLight),
                    R"({"name": "under the block", "position": [1.5, 0, 1.5], "normal": [0, 1, 0]})",
                    R"(, "camera": {"position": [1.4, 0.6, 1.4], "look_at": [3, 1, 3]})");
    CHECK(mentions(w, "/lights/0: the light at (1.5, 0.5, 1.5) is inside a closed solid"));
    CHECK_FALSE(mentions(w, "/lights/1"));
    CHECK(mentions(w, "/camera: the camera at (1.4, 0.6, 1.4) is inside a closed solid"));
    CHECK(mentions(w, "sensor \"under the block\" at (1.5, 0, 1.5) is inside a solid"));
}

TEST_CASE("a sensor buried under a carpet or behind a mirror, and a mirror wound backwards, are named", "[warnings]") {
    // A mirror 1 cm in front of the wall x = 0 facing the room, a second one wound
    // backwards (facing the wall behind it), a sensor on the wall behind the first, and
    // one on the floor under a 1 mm thin panel.
    auto w = warningsFor(
        "mirrors",
        R"(, {"type": "quad", "material": "mirror", "vertices": [[0.01, 1, 1], [0.01, 2, 1], [0.01, 2, 2], [0.01, 1, 2]]},
           {"type": "quad", "material": "mirror", "vertices": [[0.01, 1, 2.5], [0.01, 1, 3.5], [0.01, 2, 3.5], [0.01, 2, 2.5]]},
           {"type": "quad", "material": "wall", "vertices": [[2.5, 0.001, 2.5], [2.5, 0.001, 3.5], [3.5, 0.001, 3.5], [3.5, 0.001, 2.5]]},
           {"type": "quad", "material": "wall", "vertices": [[0.5, 0.001, 2.5], [1.5, 0.001, 2.5], [1.5, 0.001, 3.5], [0.5, 0.001, 3.5]]})",
        kLight,
        R"({"name": "behind mirror", "position": [0, 1.5, 1.5], "normal": [1, 0, 0]},
           {"name": "under panel", "position": [3, 0, 3], "normal": [0, 1, 0]},
           {"name": "under a face-down panel", "position": [1, 0, 3], "normal": [0, 1, 0]})");
    for (const auto& line : w) UNSCOPED_INFO(line);
    CHECK(mentions(w, "sensor \"behind mirror\" at (0, 1.5, 1.5) is behind a mirror"));
    // Under a panel 1 mm above it, facing up or down: its view is covered within 5 mm.
    CHECK(mentions(w, "sensor \"under panel\" at (3, 0, 3) is buried"));
    CHECK(mentions(w, "sensor \"under a face-down panel\" at (1, 0, 3) is buried"));
    CHECK(mentions(w, "/objects/2: the mirror at (0.01, 1.5, 3) faces nothing"));
    CHECK_FALSE(mentions(w, "/objects/1: the mirror"));
}

TEST_CASE("a camera behind a mirror (the bundled SPH4 scene) is named", "[warnings]") {
    auto scene = app::loadSceneFile(test::sourcePath("scenes/sphere/sph4.json"), {});
    auto mesh = radiosity::premesh(scene, scene.meshing);
    auto embree = raytrace::buildEmbreeScene(scene, mesh);
    CHECK(mentions(app::sceneWarnings(scene, mesh, *embree), "looks at the back of a mirror"));
}
