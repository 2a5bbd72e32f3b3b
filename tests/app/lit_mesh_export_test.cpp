// Walkthrough export: the .glb holds every diffuse patch once, its colours are
// in glTF's [0, 1], its absolute luminances agree with the solution's, and its camera
// looks where the scene's does.
#include <app/lit_mesh_export.h>
#include <app/walkthrough.h>

#include "pipeline_test_util.h"
#include "test_support.h"

#include <catch2/catch.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include <cstring>

using namespace rayrad;

namespace {

/// The JSON chunk and the binary chunk of a .glb (glTF 2.0 §4.4).
std::pair<nlohmann::json, std::string> splitGlb(const std::string& glb) {
    auto u32 = [&](size_t at) {
        uint32_t v;
        std::memcpy(&v, glb.data() + at, 4);
        return v;
    };
    REQUIRE(glb.substr(0, 4) == "glTF");
    REQUIRE(u32(4) == 2);
    REQUIRE(u32(8) == glb.size());
    const uint32_t jsonLength = u32(12);
    const auto json = nlohmann::json::parse(glb.substr(20, jsonLength));
    const size_t binAt = 20 + jsonLength;
    return {json, glb.substr(binAt + 8, u32(binAt))};
}

template <typename T>
std::vector<T> accessorData(const nlohmann::json& gltf, const std::string& bin, int accessor, int components) {
    const auto& a = gltf["accessors"][accessor];
    const auto& view = gltf["bufferViews"][a["bufferView"].get<int>()];
    std::vector<T> out(a["count"].get<size_t>() * components);
    std::memcpy(out.data(), bin.data() + view.value("byteOffset", 0), out.size() * sizeof(T));
    return out;
}

}  // namespace

TEST_CASE("the lit mesh export: every patch once, colours in range, absolute luminance kept", "[export]") {
    const std::string json = R"({"materials": {"w": {"reflectance": 0.7}, "red": {"reflectance": [0.6, 0.1, 0.1]},
                                               "lamp": {"type": "emissive", "luminance_cd_m2": 2000}},
        "objects": [{"type": "box", "min": [0, 0, 0], "max": [4, 2.8, 3], "facing": "inward", "material": "w"},
                    {"type": "box", "min": [2.5, 0, 0.5], "max": [3.5, 0.75, 1.5], "material": "red"},
                    {"type": "quad", "vertices": [[1.5, 2.79, 1], [2.5, 2.79, 1], [2.5, 2.79, 2], [1.5, 2.79, 2]], "material": "lamp"}],
        "camera": {"position": [0.5, 1.5, 2.5], "look_at": [3, 0.5, 0.5], "resolution": [64, 48]},
        "radiosity": {"max_edge": 0.1}})";
    const auto run = app::runPipeline(test::writeTempScene("export_room", json), test::quiet());
    tonemap::DisplayOptions display;
    const auto [gltf, bin] =
        splitGlb(app::exportLitMesh(run, display, app::solutionAdaptationLuminance(run), "export_room.json"));

    const auto& attributes = gltf["meshes"][0]["primitives"][0]["attributes"];
    const int indexAccessor = gltf["meshes"][0]["primitives"][0]["indices"];
    const auto indices = accessorData<uint32_t>(gltf, bin, indexAccessor, 1);
    CHECK(indices.size() == 3 * run.mesh.patches.size());
    const auto colours = accessorData<float>(gltf, bin, attributes["COLOR_0"], 3);
    const auto luminances = accessorData<float>(gltf, bin, attributes["_LUMINANCE"], 1);
    const auto positions = accessorData<float>(gltf, bin, attributes["POSITION"], 3);
    REQUIRE(colours.size() == 3 * luminances.size());
    for (float c : colours) CHECK((c >= 0 && c <= 1));
    CHECK(gltf["extensionsUsed"][0] == "KHR_materials_unlit");

    // The area-weighted mean reflected luminance over the room's patches, from the vertex
    // values the file holds (each triangle: the mean of its corners), against the same
    // mean from the solution's patch values. The two differ by the linear interpolation
    // between vertex values, which converges with the mesh: −1.5 % at 0.3 m patches,
    // −0.29 % at the 0.1 m used here.
    double fromFile = 0, fromSolution = 0, area = 0;
    for (size_t i = 0; i < run.mesh.patches.size(); ++i) {
        const auto& p = run.mesh.patches[i];
        if (run.scene.materials[p.material].isEmissive()) continue;
        double corners = 0;
        for (int k = 0; k < 3; ++k) corners += luminances[indices[3 * i + k]] / 3.0;
        fromFile += corners * p.area;
        fromSolution += luminance(run.lighting.solution.reflectedLuminance(run.scene, run.mesh, i)) * p.area;
        area += p.area;
        for (int k = 0; k < 3; ++k)  // the positions are the patch's corners
            for (int c = 0; c < 3; ++c)
                CHECK(positions[3 * indices[3 * i + k] + c] == Approx(run.mesh.corner(p, k)[c]).margin(1e-6));
    }
    INFO("file " << fromFile / area << " cd/m², solution " << fromSolution / area << " cd/m²");
    CHECK(fromFile / area == Approx(fromSolution / area).epsilon(0.01));

    // The camera: its node's −Z is the scene camera's viewing direction.
    const auto& node = gltf["nodes"][1];
    REQUIRE(node.contains("camera"));
    const glm::dquat q(node["rotation"][3].get<double>(), node["rotation"][0].get<double>(),
                       node["rotation"][1].get<double>(), node["rotation"][2].get<double>());
    const Vec3 forward = q * Vec3(0, 0, -1);
    const Vec3 expected = glm::normalize(Vec3(3, 0.5, 0.5) - Vec3(0.5, 1.5, 2.5));
    CHECK(glm::length(forward - expected) < 1e-6);
    CHECK(gltf["cameras"][0]["perspective"]["aspectRatio"].get<double>() == Approx(64.0 / 48.0));
    CHECK(gltf["scenes"][0]["extras"]["rayrad"]["adaptation_luminance_cd_m2"].get<double>() > 0);
}
