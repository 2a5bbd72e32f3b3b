// Writing a vertex-coloured triangle mesh as binary glTF 2.0 (.glb) with an unlit material:
// the walkthrough export's file format (tinygltf, like the reader).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rayrad::scene {

/// An indexed triangle mesh with a colour and one scalar per vertex.
struct ColouredMesh {
    std::vector<float> positions;   ///< x, y, z per vertex, metres (y up, as glTF)
    std::vector<float> colours;     ///< linear r, g, b per vertex, each in [0, 1] (glTF COLOR_0)
    std::vector<float> scalar;      ///< one value per vertex, written as attribute `scalarName`
    std::string scalarName;         ///< an application-specific attribute: starts with "_"
    std::vector<uint32_t> indices;  ///< three per triangle, counter-clockwise seen from the front
};

/// A perspective camera for the file's viewers (glTF cameras look down their node's −Z).
struct GlbCamera {
    float position[3] = {0, 0, 0};
    float rotation[4] = {0, 0, 0, 1};  ///< unit quaternion x, y, z, w: the camera's frame in the world
    double verticalFovRad = 0.785;
    double aspect = 1;                 ///< width / height
};

/// Text and number entries for the scene's `extras` (for the reader of the file).
struct GlbExtras {
    std::vector<std::pair<std::string, std::string>> text;
    std::vector<std::pair<std::string, double>> numbers;
};

/// The .glb bytes: one node, one mesh, one primitive (POSITION with its bounds, COLOR_0,
/// the scalar attribute, indices) and the camera's node when given, a material marked KHR_materials_unlit whose base colour
/// is white (so the vertex colours are what is seen), `extras` under the scene as
/// {"rayrad": {...}}. Throws std::invalid_argument for inconsistent array sizes.
std::string encodeColouredGlb(const ColouredMesh& mesh, const GlbExtras& extras, const std::string& generator,
                              const std::optional<GlbCamera>& camera = std::nullopt);

}  // namespace rayrad::scene
