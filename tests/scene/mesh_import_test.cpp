// Mesh files: PLY (ASCII, binary of both byte orders, broken and hostile), OBJ with .mtl
// materials, glTF with materials and KHR_lights_punctual. No input may crash the importer.
#include <core/input_error.h>
#include <scene/mesh_import.h>
#include <scene/scene.h>
#include <scene/scene_parser.h>

#include "test_support.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

using namespace rayrad;
using namespace rayrad::scene;

namespace {

/// Writes a PLY file with float x, y, z vertices and a face list (count type uchar, index
/// type int), in the given format; `vertexCount`/`faceCount` < 0 take the real counts.
/// `cut` > 0 truncates the file to that many bytes.
std::string writePly(const std::string& name, const std::vector<std::array<float, 3>>& vertices,
                     const std::vector<std::vector<int>>& faces, const std::string& format = "binary_little_endian",
                     long long vertexCount = -1, long long faceCount = -1, size_t cut = 0) {
    std::string header = "ply\nformat " + format + " 1.0\ncomment rayrad test\n";
    header += "element vertex " + std::to_string(vertexCount < 0 ? (long long)vertices.size() : vertexCount) + "\n";
    header += "property float x\nproperty float y\nproperty float z\n";
    header += "element face " + std::to_string(faceCount < 0 ? (long long)faces.size() : faceCount) + "\n";
    header += "property list uchar int vertex_indices\nend_header\n";
    std::string body;
    const bool ascii = format == "ascii", big = format == "binary_big_endian";
    auto put = [&](const void* p, size_t n) {
        std::string bytes(static_cast<const char*>(p), n);
        if (big) std::reverse(bytes.begin(), bytes.end());  // this machine is little endian
        body += bytes;
    };
    for (const auto& v : vertices) {
        if (ascii) body += std::to_string(v[0]) + " " + std::to_string(v[1]) + " " + std::to_string(v[2]) + "\n";
        else for (float x : v) put(&x, 4);
    }
    for (const auto& f : faces) {
        if (ascii) {
            body += std::to_string(f.size());
            for (int i : f) body += " " + std::to_string(i);
            body += "\n";
        } else {
            auto n = static_cast<unsigned char>(f.size());
            put(&n, 1);
            for (int i : f) put(&i, 4);
        }
    }
    std::string all = header + body;
    if (cut > 0) all.resize(cut);
    std::string path = "/tmp/rayrad_test_" + name;
    std::ofstream(path, std::ios::binary) << all;
    return path;
}

const std::vector<std::array<float, 3>> kVertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}};

/// The importer's error for a file, or "" when it loads.
std::string importError(const std::string& path) {
    try {
        importMesh(path, "scene.json", "/objects/0");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("PLY: ASCII, binary little and big endian give the same triangles and quads are triangulated",
          "[scene][import]") {
    std::string format = GENERATE("ascii", "binary_little_endian", "binary_big_endian");
    auto mesh = importMesh(writePly("tri_" + format + ".ply", kVertices, {{0, 1, 2}, {0, 2, 3}, {0, 1, 4}}, format),
                           "scene.json", "/objects/0");
    CHECK(mesh.triangles.size() == 3);
    CHECK(mesh.positions.size() == 5);
    CHECK(mesh.positions[2] == Vec3(1, 1, 0));
    auto quads = importMesh(writePly("quad_" + format + ".ply", kVertices, {{0, 1, 2, 3}, {0, 1, 4}}, format),
                            "scene.json", "/objects/0");
    CHECK(quads.triangles.size() == 3);
}

TEST_CASE("PLY: broken and hostile files give a clear error naming the problem, never a crash", "[scene][import]") {
    CHECK_THAT(importError(writePly("bad_huge.ply", kVertices, {{0, 1, 2}}, "binary_little_endian", 4000000000LL)),
               Catch::Contains("claims 4000000000 records"));
    CHECK_THAT(importError(writePly("bad_short.ply", kVertices, {{0, 1, 2}}, "binary_little_endian", -1, 1000)),
               Catch::Contains("element 'face' claims 1000 records"));
    CHECK_THAT(importError(writePly("bad_cut.ply", kVertices, {{0, 1, 2}}, "binary_little_endian", -1, -1, 190)),
               Catch::Contains("claims"));
    CHECK_THAT(importError(writePly("bad_negative.ply", kVertices, {{0, 1, 2}, {0, -1, 3}})),
               Catch::Contains("face 1: vertex index -1 is not a valid index"));
    CHECK_THAT(importError(writePly("bad_nan.ply", {{0, 0, 0}, {std::nanf(""), 0, 0}, {1, 1, 0}}, {{0, 1, 2}})),
               Catch::Contains("vertex 1 is not finite"));
    CHECK_THAT(importError(writePly("bad_nofaces.ply", kVertices, {})), Catch::Contains("has no triangles"));
    {
        std::ofstream("/tmp/rayrad_test_bad_garbage.ply", std::ios::binary)
            << "ply\nformat binary_little_endian 1.0\n" << std::string(300, '\xff');
        CHECK_THAT(importError("/tmp/rayrad_test_bad_garbage.ply"), Catch::Contains("header line 3"));
        std::ofstream("/tmp/rayrad_test_bad_empty.ply", std::ios::binary);
        CHECK_THAT(importError("/tmp/rayrad_test_bad_empty.ply"), Catch::Contains("ends before end_header"));
    }
    // Out-of-range indices and lines are dropped and counted; the rest loads.
    auto mesh = importMesh(writePly("bad_range.ply", kVertices, {{0, 1, 2}, {0, 7, 99999999}, {0, 1}}), "scene.json",
                           "/objects/0");
    CHECK(mesh.triangles.size() == 1);
    CHECK(mesh.droppedFaces == 2);
}

TEST_CASE("a Git LFS pointer in place of a mesh, or of a glTF's buffer, is named as one", "[scene][import]") {
    // A repository cloned without Git LFS holds these few lines in place of its binaries:
    // as a PLY they read as a broken header, as a glTF buffer as a size mismatch.
    const std::string pointer =
        "version https://git-lfs.github.com/spec/v1\n"
        "oid sha256:3e56584aaa453e1c72226646de4af1f777d69f01d497d7a26cf806c8005ea322\nsize 108\n";
    const std::string ply = "/tmp/rayrad_test_lfs.ply", bin = "/tmp/rayrad_test_lfs.bin",
                      gltf = "/tmp/rayrad_test_lfs.gltf";
    std::ofstream(ply, std::ios::binary) << pointer;
    std::ofstream(bin, std::ios::binary) << pointer;
    std::ofstream(gltf) << R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 108, "uri": "rayrad_test_lfs.bin"}],
      "bufferViews": [{"buffer": 0, "byteLength": 36}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                     "min": [0, 0, 0], "max": [1, 1, 0]}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
      "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})";
    for (const std::string& file : {ply, gltf}) {
        const std::string error = importError(file);
        INFO(file << ": " << error);
        CHECK(error.find("Git LFS pointer") != std::string::npos);
        CHECK(error.find("git lfs pull") != std::string::npos);
    }
    CHECK(importError(gltf).find("rayrad_test_lfs.bin") != std::string::npos);
}

TEST_CASE("PLY: every truncation of a binary file loads or gives an InputError", "[scene][import]") {
    std::string path = writePly("whole.ply", kVertices, {{0, 1, 2}, {0, 2, 3, 4}, {1, 2, 4}});
    std::ifstream in(path, std::ios::binary);
    std::string whole((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (size_t n = 0; n < whole.size(); n += 3) {
        std::ofstream("/tmp/rayrad_test_cut.ply", std::ios::binary) << whole.substr(0, n);
        INFO("first " << n << " bytes");
        std::string error = importError("/tmp/rayrad_test_cut.ply");
        CHECK((error.empty() || error.find("rayrad_test_cut.ply") != std::string::npos));
    }
}

TEST_CASE("OBJ with .mtl: usemtl groups become materials (Kd reflectance, Ke emission) and a JSON material overrides",
          "[scene][import]") {
    std::ofstream("/tmp/rayrad_test_room.mtl") << "newmtl wall\nKd 0.6 0.5 0.4\n\nnewmtl lamp\nKd 0 0 0\nKe 100 100 100\n"
                                                  "map_Kd wall.png\n";
    std::ofstream("/tmp/rayrad_test_room.obj") << "mtllib rayrad_test_room.mtl\n"
                                                  "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\n"
                                                  "usemtl wall\nf 1 2 3 4\nusemtl lamp\nf 1 2 6\nf 1 6 5\n";
    auto mesh = importMesh("/tmp/rayrad_test_room.obj", "scene.json", "/objects/0");
    REQUIRE(mesh.materials.size() == 2);
    REQUIRE(mesh.triangles.size() == 4);
    CHECK(mesh.positions.size() == 6);  // shared corners
    const ImportedMaterial* wall = nullptr;
    const ImportedMaterial* lamp = nullptr;
    for (const auto& m : mesh.materials) (m.name == "wall" ? wall : lamp) = &m;
    REQUIRE(wall);
    REQUIRE(lamp);
    CHECK(wall->reflectance.r == Approx(0.6));
    CHECK(wall->reflectance.b == Approx(0.4));
    CHECK(lamp->emission.g == Approx(100));
    CHECK(lamp->diffuseTexture == "wall.png");

    auto build = [](const std::string& material) {
        std::string json = R"({"materials": {"grey": {"reflectance": 0.3}},
            "objects": [{"type": "mesh", "file": "/tmp/rayrad_test_room.obj")" + material + R"(}],
            "lights": [{"type": "point", "position": [0.5, 0.5, 0.5], "intensity_cd": 1}]})";
        std::ofstream("/tmp/rayrad_test_obj_scene.json") << json;
        return buildScene(loadScene("/tmp/rayrad_test_obj_scene.json"));
    };
    Scene fromFile = build("");
    CHECK(fromFile.groups.size() == 2);
    bool sawLamp = false;
    for (const auto& g : fromFile.groups)
        if (fromFile.materials[g.material].isEmissive()) {
            sawLamp = true;
            CHECK(g.polygons.size() == 2);
        }
    CHECK(sawLamp);
    Scene overridden = build(R"(, "material": "grey")");
    REQUIRE(overridden.groups.size() == 1);
    CHECK(overridden.materials[overridden.groups[0].material].name == "grey");
}

TEST_CASE("glTF: baseColorFactor, node transforms and KHR_lights_punctual point and spot lights in candela",
          "[scene][import]") {
    // One triangle at z = 2 (node translation), a red material, a point light (colour
    // × 100 cd) and a spot turned 90° about x (its −z axis becomes +y).
    const char* gltf = R"({"asset": {"version": "2.0"}, "extensionsUsed": ["KHR_lights_punctual"],
      "extensions": {"KHR_lights_punctual": {"lights": [
        {"name": "bulb", "type": "point", "color": [1, 0.5, 0.25], "intensity": 100},
        {"name": "spot", "type": "spot", "intensity": 50, "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.5}}]}},
      "scene": 0, "scenes": [{"nodes": [0, 1, 2]}],
      "nodes": [{"mesh": 0, "translation": [0, 0, 2]},
                {"name": "bulbnode", "translation": [0.2, 0.3, 3], "extensions": {"KHR_lights_punctual": {"light": 0}}},
                {"name": "spotnode", "translation": [1, 1, 4], "rotation": [0.70710678, 0, 0, 0.70710678],
                 "extensions": {"KHR_lights_punctual": {"light": 1}}}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
      "materials": [{"name": "red", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.1, 0.1, 1]}}],
      "buffers": [{"byteLength": 44, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIAAAA="}],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0,0,0], "max": [1,1,0]},
                    {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}]})";
    std::ofstream("/tmp/rayrad_test_tri.gltf") << gltf;
    auto mesh = importMesh("/tmp/rayrad_test_tri.gltf", "scene.json", "/objects/0");
    REQUIRE(mesh.triangles.size() == 1);
    CHECK(mesh.positions[0] == Vec3(0, 0, 2));
    REQUIRE(mesh.triangleMaterial[0] >= 0);
    CHECK(mesh.materials[mesh.triangleMaterial[0]].name == "red");
    CHECK(mesh.materials[mesh.triangleMaterial[0]].reflectance.r == Approx(0.8));
    REQUIRE(mesh.lights.size() == 2);
    const ImportedLight& bulb = mesh.lights[0].isSpot ? mesh.lights[1] : mesh.lights[0];
    const ImportedLight& spot = mesh.lights[0].isSpot ? mesh.lights[0] : mesh.lights[1];
    CHECK(bulb.position.x == Approx(0.2));
    CHECK(bulb.position.z == Approx(3));
    CHECK(bulb.intensity.r == Approx(100));
    CHECK(bulb.intensity.b == Approx(25));
    CHECK(spot.direction.y == Approx(1).margin(1e-6));
    CHECK(spot.innerAngleDeg == Approx(0.2 * 180 / kPi));
    CHECK(spot.outerAngleDeg == Approx(0.5 * 180 / kPi));
}

TEST_CASE("glTF: a mirroring node keeps its faces' side, and doubleSided, transmission, metal, cameras and lights "
          "rayrad cannot take are honoured or named",
          "[scene][import]") {
    // The triangle (0,0,0), (1,0,0), (0,1,0) faces +z; the node mirrors x (scale −1), which
    // by the specification reverses the winding, so it still faces +z.
    const char* gltf = R"({"asset": {"version": "2.0"}, "extensionsUsed": ["KHR_lights_punctual",
        "KHR_materials_transmission", "KHR_materials_ior"],
      "extensions": {"KHR_lights_punctual": {"lights": [
        {"name": "sun", "type": "directional", "intensity": 3},
        {"name": "dark", "type": "point", "intensity": -5}]}},
      "scene": 0, "scenes": [{"nodes": [0, 1, 2, 3, 4]}],
      "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}],
      "nodes": [{"mesh": 0, "scale": [-1, 1, 1]}, {"mesh": 1}, {"mesh": 2},
                {"extensions": {"KHR_lights_punctual": {"light": 0}}},
                {"extensions": {"KHR_lights_punctual": {"light": 1}}}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]},
                 {"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 1}]},
                 {"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 2}]}],
      "materials": [{"name": "paper", "doubleSided": true, "pbrMetallicRoughness": {"metallicFactor": 0}},
                    {"name": "glass", "pbrMetallicRoughness": {"metallicFactor": 0},
                     "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1},
                                    "KHR_materials_ior": {"ior": 1.45}}},
                    {"name": "chrome", "pbrMetallicRoughness": {"metallicFactor": 1, "roughnessFactor": 0.05}}],
      "buffers": [{"byteLength": 44, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIAAAA="}],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0,0,0], "max": [1,1,0]},
                    {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}]})";
    std::ofstream("/tmp/rayrad_test_mirrored.gltf") << gltf;
    const auto mesh = importMesh("/tmp/rayrad_test_mirrored.gltf", "scene.json", "/objects/0");
    REQUIRE(mesh.triangles.size() == 3);
    const auto& t = mesh.triangles[0];
    const Vec3 n = glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]], mesh.positions[t[2]] - mesh.positions[t[0]]);
    CHECK(mesh.positions[t[0]].x + mesh.positions[t[1]].x + mesh.positions[t[2]].x == Approx(-1));  // mirrored
    CHECK(n.z > 0);
    REQUIRE(mesh.materials.size() == 3);
    CHECK(mesh.materials[0].twoSided);
    CHECK(mesh.materials[1].glass);
    CHECK(mesh.materials[1].ior == Approx(1.45));
    auto said = [](const std::vector<std::string>& lines, const std::string& what) {
        for (const auto& l : lines)
            if (l.find(what) != std::string::npos) return true;
        return false;
    };
    CHECK(mesh.materials[2].mirrorLike);  // polished: the builder makes it a mirror where flat
    CHECK(!said(mesh.materialWarnings, "chrome"));
    CHECK(!said(mesh.materialWarnings, "paper"));
    CHECK(mesh.cameras.empty());  // the file lists a camera, but no node places it
    CHECK(said(mesh.warnings, "\"sun\" is directional: left out"));
    CHECK(said(mesh.warnings, "\"dark\": its intensity (-5 × colour) is negative or not finite: left out"));
    CHECK(mesh.lights.empty());
}

TEST_CASE("glTF: cameras placed by their nodes become named views of the scene", "[scene][import]") {
    // "side" at (1, 2, 3) turned 90° about y (looking along −x), yfov 0.8 rad, aspect 1.5;
    // "plan" orthographic, turned −90° about x (looking down), xmag 2, ymag 1.
    const char* gltf = R"({"asset": {"version": "2.0"},
      "scene": 0, "scenes": [{"nodes": [0, 1, 2]}],
      "cameras": [{"name": "side", "type": "perspective", "perspective": {"yfov": 0.8, "aspectRatio": 1.5, "znear": 0.1}},
                  {"name": "plan", "type": "orthographic", "orthographic": {"xmag": 2, "ymag": 1, "znear": 0.1, "zfar": 10}}],
      "nodes": [{"mesh": 0},
                {"camera": 0, "translation": [1, 2, 3], "rotation": [0, 0.70710678, 0, 0.70710678]},
                {"camera": 1, "translation": [0, 5, 0], "rotation": [-0.70710678, 0, 0, 0.70710678]}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
      "buffers": [{"byteLength": 44, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIAAAA="}],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0,0,0], "max": [1,1,0]},
                    {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}]})";
    std::ofstream("/tmp/rayrad_test_cameras.gltf") << gltf;
    const auto mesh = importMesh("/tmp/rayrad_test_cameras.gltf", "scene.json", "/objects/0");
    REQUIRE(mesh.cameras.size() == 2);
    const ImportedCamera& side = mesh.cameras[0];
    CHECK(side.name == "side");
    CHECK(side.position.x == Approx(1));
    CHECK(side.position.z == Approx(3));
    CHECK(side.direction.x == Approx(-1).margin(1e-6));
    CHECK(side.up.y == Approx(1).margin(1e-6));
    CHECK(side.yfovDeg == Approx(0.8 * 180 / kPi));
    CHECK(side.aspectRatio == Approx(1.5));
    const ImportedCamera& plan = mesh.cameras[1];
    CHECK(plan.orthographic);
    CHECK(plan.direction.y == Approx(-1).margin(1e-6));
    CHECK(plan.up.z == Approx(-1).margin(1e-6));

    // In a scene: moved 10 m along x by the object's transform; views after the scene's own.
    const std::string sceneFile = "/tmp/rayrad_test_cameras.json";
    std::ofstream(sceneFile) << R"({"materials": {"m": {"reflectance": 0.5}},
      "objects": [{"type": "mesh", "file": "rayrad_test_cameras.gltf", "material": "m",
                   "transform": {"translate": [10, 0, 0]}}],
      "lights": [{"type": "point", "position": [0, 1, 0], "intensity_cd": 1}],
      "cameras": [{"name": "mine", "position": [0, 1, 5], "look_at": [0, 0, 0]}]})";
    const SceneDesc desc = loadScene(sceneFile);
    REQUIRE(desc.views.size() == 3);
    CHECK(desc.views[0].first == "mine");
    CHECK(desc.camera->position.z == Approx(5));  // the scene's own stays the default
    CHECK(desc.views[1].first == "side");
    const CameraDesc& c = desc.views[1].second;
    CHECK(c.position.x == Approx(11));
    CHECK(c.lookAt.x == Approx(10).margin(1e-6));
    CHECK(c.verticalFovDeg == Approx(0.8 * 180 / kPi));
    CHECK(c.width == 720);
    CHECK(c.height == 480);
    CHECK(desc.views[2].second.projection == Projection::Orthographic);
    CHECK(desc.views[2].second.orthoHeight == Approx(2));

    // A file camera named like a view of the scene is refused.
    std::ofstream(sceneFile) << R"({"materials": {"m": {"reflectance": 0.5}},
      "objects": [{"type": "mesh", "file": "rayrad_test_cameras.gltf", "material": "m"}],
      "lights": [{"type": "point", "position": [0, 1, 0], "intensity_cd": 1}],
      "cameras": [{"name": "side", "position": [0, 1, 5], "look_at": [0, 0, 0]}]})";
    CHECK_THROWS_WITH(loadScene(sceneFile), Catch::Contains("/objects/0/file") &&
                                                Catch::Contains("the file's camera \"side\" has the name of a view"));
}

TEST_CASE("glTF: polished metal on a plane becomes a mirror, curved or rough metal stays diffuse and says so",
          "[scene][import]") {
    // Two triangles of "chrome" in the plane z = 0 (a square mirror), one of "bent chrome"
    // tilted out of it together with one in it, and one of "brushed" (roughness 0.5).
    const char* gltf = R"({"asset": {"version": "2.0"},
      "scene": 0, "scenes": [{"nodes": [0, 1, 2]}],
      "nodes": [{"mesh": 0}, {"mesh": 1, "translation": [0, 0, 1]}, {"mesh": 2, "translation": [0, 0, 2]}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]},
                 {"primitives": [{"attributes": {"POSITION": 2}, "indices": 1, "material": 1}]},
                 {"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 2}]}],
      "materials": [{"name": "chrome", "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.9, 0.9, 1], "metallicFactor": 1, "roughnessFactor": 0}},
                    {"name": "bent chrome", "pbrMetallicRoughness": {"metallicFactor": 1, "roughnessFactor": 0}},
                    {"name": "brushed", "pbrMetallicRoughness": {"metallicFactor": 1, "roughnessFactor": 0.5}}],
      "buffers": [{"byteLength": 108, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAACAPwAAgD8AAAAAAAAAAAAAgD8AAAAAAAABAAIAAAACAAMAAAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAACAPwAAgD8AAIA/AAAAAAAAgD8AAAAA"}],
      "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 12},
                      {"buffer": 0, "byteOffset": 60, "byteLength": 48}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0,0,0], "max": [1,1,0]},
                    {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"},
                    {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0,0,0], "max": [1,1,1]}]})";
    std::ofstream("/tmp/rayrad_test_metal.gltf") << gltf;
    const std::string sceneFile = "/tmp/rayrad_test_metal.json";
    std::ofstream(sceneFile) << R"({"materials": {"white": {"reflectance": 0.5}},
      "objects": [{"type": "mesh", "file": "rayrad_test_metal.gltf"},
                  {"type": "box", "min": [-3, -3, -3], "max": [4, 4, 6], "facing": "inward", "material": "white"}],
      "lights": [{"type": "point", "position": [0.5, 0.5, 4], "intensity_cd": 10}]})";
    const Scene scene = buildScene(loadScene(sceneFile));
    REQUIRE(scene.mirrors.size() == 2);  // the square's two triangles
    CHECK(scene.mirrors[0].normal.z == Approx(1));
    CHECK(scene.mirrors[0].specular.r == Approx(0.9));
    auto said = [&](const std::string& what) {
        for (const auto& l : scene.warnings.fileWarnings)
            if (l.find(what) != std::string::npos) return true;
        return false;
    };
    CHECK(said("material \"chrome\" is polished metal on a plane: read as a mirror"));
    CHECK(said("material \"bent chrome\" is polished metal, but its 2 triangles do not lie in one plane"));
    CHECK(said("material \"brushed\" is metallic (metallicFactor 1, roughness 0.5): read as diffuse"));
}
