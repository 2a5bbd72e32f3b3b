// The parser reports every problem with its place (JSON pointer or line/column).
#include <core/input_error.h>
#include <scene/scene.h>
#include <scene/scene_parser.h>

#include "scene/scene_test_util.h"
#include "test_support.h"

using namespace rayrad;
using namespace rayrad::test;

TEST_CASE("a valid scene parses without errors", "[parser]") {
    auto e = parseErrors(boxScene());
    CHECK(e.messages.empty());
    auto desc = scene::parseScene(boxScene(), "test.json");
    REQUIRE(desc.objects.size() == 1);
    CHECK(desc.lights[0].intensity == 100.0);
}

TEST_CASE("malformed JSON names the line and column", "[parser]") {
    auto e = parseErrors("{\n  \"materials\": {,\n}");
    REQUIRE(e.messages.size() == 1);
    CHECK(e.contains("line 2, column"));
    CHECK(e.contains("invalid JSON"));
}

TEST_CASE("the default handler throws one InputError naming file and place", "[parser]") {
    std::string bad = boxScene(R"({"type": "diffuse", "reflectance": 0.5})",
                               R"({"type": "point", "position": [0,0,0], "intensity_cd": -5})");
    try {
        scene::parseScene(bad, "scenes/cube.json");
        FAIL("no error");
    } catch (const InputError& err) {
        CHECK(std::string(err.what()) == "scenes/cube.json: /lights/0/intensity_cd: expected a positive number, got -5");
    }
}

TEST_CASE("reflectance must be at least 0 and below 1", "[parser]") {
    CHECK(parseErrors(boxScene(R"({"type": "diffuse", "reflectance": 1.0})")).contains("/materials/grey/reflectance"));
    CHECK(parseErrors(boxScene(R"({"type": "diffuse", "reflectance": [0.5, -0.1, 0.2]})")).contains("/materials/grey/reflectance"));
    CHECK(parseErrors(boxScene(R"({"type": "diffuse", "reflectance": 0.99})")).messages.empty());
}

TEST_CASE("unknown keys and names get a did-you-mean", "[parser]") {
    auto e = parseErrors(boxScene(R"({"type": "diffuse", "reflectence": 0.5})"));
    CHECK(e.contains("/materials/grey/reflectence: unknown key (did you mean \"reflectance\"?)"));
    std::string s = R"({"materials": {"white": {"reflectance": 0.5}},
        "objects": [{"type": "quad", "material": "whte", "vertices": [[0,0,0],[1,0,0],[1,1,0],[0,1,0]]}],
        "lights": [{"type": "point", "position": [0,0,1], "intensity_cd": 1}]})";
    CHECK(parseErrors(s).contains("/objects/0/material: unknown material \"whte\" (did you mean \"white\"?)"));
}

TEST_CASE("NaN and infinity are rejected", "[parser]") {
    auto e = parseErrors(boxScene(R"({"type": "diffuse", "reflectance": 0.5})",
                                  R"({"type": "point", "position": [0,0,0], "intensity_cd": "NaN"})"));
    CHECK(e.contains("/lights/0/intensity_cd: expected a finite number"));
    auto e2 = parseErrors(boxScene(R"({"type": "diffuse", "reflectance": 0.5})",
                                   R"({"type": "point", "position": [0, 1e999, 0], "intensity_cd": 1})"));
    CHECK(e2.contains("line 3, column"));
    CHECK(e2.contains("number overflow"));
}

TEST_CASE("wrong types and shapes are named", "[parser]") {
    std::string s = R"({"materials": {"m": {"reflectance": 0.5}},
        "objects": [{"type": "quad", "material": "m", "vertices": [[0,0,0],[1,0,0],[1,1,0]]}],
        "lights": [{"type": "point", "position": "here", "intensity_cd": 1}]})";
    auto e = parseErrors(s);
    CHECK(e.contains("/objects/0/vertices: a quad needs 4 vertices, got 3"));
    CHECK(e.contains("/lights/0/position: expected three finite numbers"));
}

TEST_CASE("a scene without light or geometry is an error", "[parser]") {
    CHECK(parseErrors(R"({"materials": {}, "objects": []})").contains("/objects: the scene has no geometry"));
    std::string noLight = R"({"materials": {"m": {"reflectance": 0.5}},
        "objects": [{"type": "box", "min": [0,0,0], "max": [1,1,1], "material": "m"}]})";
    CHECK(parseErrors(noLight).contains("/lights: the scene has no light"));
}

TEST_CASE("command-line overrides are applied and checked like the file", "[parser]") {
    auto desc = scene::parseScene(boxScene(), "t.json", {scene::parseOverride("radiosity.max_edge=0.25"),
                                                          scene::parseOverride("lights.0.intensity_cd=7")});
    CHECK(desc.meshing.maxEdge == 0.25);
    CHECK(desc.lights[0].intensity == 7.0);
    CHECK(parseErrors(boxScene(), {scene::parseOverride("radiosity.max_egde=1")})
              .contains("/radiosity/max_egde: unknown key (did you mean \"max_edge\"?)"));
    CHECK_THROWS_AS(scene::parseOverride("novalue"), InputError);
}

TEST_CASE("a missing mesh file is named with its place", "[parser]") {
    std::string s = R"({"materials": {"m": {"reflectance": 0.5}},
        "objects": [{"type": "mesh", "material": "m", "file": "nowhere.obj"}],
        "lights": [{"type": "point", "position": [0,0,1], "intensity_cd": 1}]})";
    auto desc = scene::parseScene(s, "dir/scene.json");
    try {
        scene::buildScene(desc);
        FAIL("no error");
    } catch (const InputError& err) {
        std::string what = err.what();
        CHECK(what.find("dir/scene.json: /objects/0/file: mesh file 'dir/nowhere.obj': no such file") == 0);
    }
}

TEST_CASE("area lights: flux in lm becomes luminance L = Φ / (π A)", "[parser]") {
    std::string s = R"({"materials": {"lamp": {"type": "emissive", "flux_lm": 100, "reflectance": 0}},
        "objects": [{"type": "quad", "material": "lamp", "vertices": [[0,0,0],[2,0,0],[2,0.5,0],[0,0.5,0]]}]})";
    auto scene = scene::buildScene(scene::parseScene(s, "t.json"));
    CHECK(luminance(scene.materials[0].emission) == Approx(100.0 / (kPi * 1.0)));
}

TEST_CASE("sensor grids expand to named points at cell centres", "[parser]") {
    std::string s = boxScene();
    s.insert(s.size() - 1, R"(, "sensor_grids": [{"name": "g", "origin": [0,0,0], "u": [1,0,0], "v": [0,1,0], "counts": [2, 3]}])");
    auto desc = scene::parseScene(s, "t.json");
    REQUIRE(desc.sensors.size() == 6);
    CHECK(desc.sensors[0].name == "g[0,0]");
    CHECK(desc.sensors[0].position == Vec3(0.25, 1.0 / 6, 0));
    CHECK(desc.sensors[5].normal == Vec3(0, 0, 1));
}

TEST_CASE("a sensor name used twice is an error: single sensors, two grids of one name, a sensor named like a grid point", "[parser]") {
    auto withSensors = [](const std::string& sensors, const std::string& grids) {
        std::string s = boxScene();
        s.insert(s.size() - 1, ", \"sensors\": [" + sensors + "], \"sensor_grids\": [" + grids + "]");
        return parseErrors(s);
    };
    auto single = [](const std::string& name) {
        return R"({"name": ")" + name + R"(", "position": [0.5,0.5,0.5], "normal": [0,0,1]})";
    };
    auto grid = [](const std::string& name, int nu, int nv) {
        return R"({"name": ")" + name + R"(", "origin": [0,0,0], "u": [1,0,0], "v": [0,1,0], "counts": [)" +
               std::to_string(nu) + ", " + std::to_string(nv) + "]}";
    };
    CHECK(withSensors(single("a") + ", " + single("b"), grid("g", 2, 2) + ", " + grid("h", 3, 1)).messages.empty());
    // A single sensor named like a grid, or like a point of another grid, is no clash.
    CHECK(withSensors(single("g") + ", " + single("g[5,5]"), grid("g", 2, 2)).messages.empty());
    CHECK(withSensors(single("a") + ", " + single("a"), "").contains("sensor name \"a\" is used twice"));
    CHECK(withSensors(single("g[1,0]"), grid("g", 2, 2)).contains("sensor name \"g[1,0]\" is used twice"));
    // Two grids of one name one after the other: their common cells clash, the others not.
    auto two = withSensors("", grid("g", 2, 1) + ", " + grid("g", 1, 2));
    CHECK(two.contains("sensor name \"g[0,0]\" is used twice"));
    CHECK_FALSE(two.contains("g[1,0]"));
    CHECK_FALSE(two.contains("g[0,1]"));
    // A grid whose name holds a bracket: its points' names end in the last one.
    CHECK(withSensors(single("a[1[0,0]"), grid("a[1", 1, 1)).contains("sensor name \"a[1[0,0]\" is used twice"));
}

TEST_CASE("named views: cameras need a unique name, all is reserved, the first is the default", "[scene]") {
    const std::string cam = R"("position": [0.5, 0.5, 0.1], "look_at": [0.5, 0.5, 1])";
    auto withCameras = [&](const std::string& cameras) {
        std::string json = test::boxScene();
        return json.substr(0, json.rfind('}')) + ", \"cameras\": [" + cameras + "]}";
    };
    const auto desc = scene::parseScene(withCameras("{\"name\": \"a\", " + cam + "}, {\"name\": \"b\", " + cam + "}"), "v.json");
    REQUIRE(desc.views.size() == 2);
    CHECK(desc.views[1].first == "b");
    CHECK(desc.camera);
    CHECK(test::parseErrors(withCameras("{\"name\": \"a\", " + cam + "}, {\"name\": \"a\", " + cam + "}"))
              .contains("/cameras/1/name: the view name \"a\" is used twice"));
    CHECK(test::parseErrors(withCameras("{\"name\": \"all\", " + cam + "}")).contains("/cameras/0/name: \"all\" is reserved"));
    CHECK(test::parseErrors(withCameras("{" + cam + "}")).contains("/cameras/0"));
}

TEST_CASE("camera projections: names, an orthographic height, a view from a sensor", "[scene]") {
    auto withCamera = [&](const std::string& camera) {
        std::string json = boxScene();
        return json.substr(0, json.rfind('}')) +
               ", \"sensors\": [{\"name\": \"S\", \"position\": [0.5, 0, 0.5], \"normal\": [0, 1, 0]}], \"camera\": {" + camera + "}}";
    };
    CHECK(parseErrors(withCamera(R"("position": [0.5, 0.5, 0.1], "look_at": [0.5, 0.5, 1], "projection": "cylindrical")"))
              .contains("/camera/projection: expected \"perspective\", \"fisheye\" or \"orthographic\""));
    CHECK(parseErrors(withCamera(R"("position": [0.5, 0.5, 0.1], "look_at": [0.5, 0.5, 1], "projection": "orthographic")"))
              .contains("/camera: missing required key \"height_m\""));
    CHECK(parseErrors(withCamera(R"("from_sensor": "S", "position": [0.5, 0.5, 0.1])"))
              .contains("/camera/position: give either \"from_sensor\" or \"position\""));
    const auto s = scene::buildScene(scene::parseScene(withCamera(R"("from_sensor": "S", "projection": "fisheye")"), "c.json"));
    REQUIRE(s.camera);
    CHECK(s.camera->position.y == Approx(1e-3));
    CHECK(s.camera->lookAt.y > s.camera->position.y);
    CHECK(s.camera->projection == scene::Projection::Fisheye);
    CHECK_THROWS_WITH(scene::buildScene(scene::parseScene(withCamera(R"("from_sensor": "T")"), "c.json")),
                      Catch::Contains("/camera/from_sensor: no sensor \"T\""));
}
