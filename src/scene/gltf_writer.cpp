#include <scene/gltf_writer.h>

// The implementation is compiled once, in gltf_reader.cpp, with these same switches.
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace rayrad::scene {

namespace {

/// Appends `values` to the buffer (4-byte aligned) as one buffer view and accessor; returns
/// the accessor's index.
template <typename T>
int addAccessor(tinygltf::Model& model, const std::vector<T>& values, int components, int componentType, int type,
                int target) {
    auto& data = model.buffers[0].data;
    while (data.size() % 4 != 0) data.push_back(0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = data.size();
    view.byteLength = values.size() * sizeof(T);
    view.target = target;
    data.resize(data.size() + view.byteLength);
    std::memcpy(data.data() + view.byteOffset, values.data(), view.byteLength);
    model.bufferViews.push_back(view);
    tinygltf::Accessor accessor;
    accessor.bufferView = static_cast<int>(model.bufferViews.size()) - 1;
    accessor.componentType = componentType;
    accessor.count = values.size() / static_cast<size_t>(components);
    accessor.type = type;
    model.accessors.push_back(accessor);
    return static_cast<int>(model.accessors.size()) - 1;
}

}  // namespace

std::string encodeColouredGlb(const ColouredMesh& mesh, const GlbExtras& extras, const std::string& generator,
                              const std::optional<GlbCamera>& camera) {
    const size_t n = mesh.positions.size() / 3;
    if (mesh.positions.size() != 3 * n || mesh.colours.size() != 3 * n || mesh.scalar.size() != n ||
        mesh.indices.size() % 3 != 0 || mesh.scalarName.empty() || mesh.scalarName[0] != '_')
        throw std::invalid_argument("encodeColouredGlb: inconsistent mesh arrays");
    for (uint32_t i : mesh.indices)
        if (i >= n) throw std::invalid_argument("encodeColouredGlb: an index beyond the vertices");

    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = generator;
    model.buffers.emplace_back();
    model.extensionsUsed.push_back("KHR_materials_unlit");

    const int position = addAccessor(model, mesh.positions, 3, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3,
                                     TINYGLTF_TARGET_ARRAY_BUFFER);
    // POSITION must state its bounds (glTF 2.0 §3.7.2.1).
    std::vector<double> lo(3, std::numeric_limits<double>::infinity()), hi(3, -std::numeric_limits<double>::infinity());
    for (size_t i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], static_cast<double>(mesh.positions[3 * i + k]));
            hi[k] = std::max(hi[k], static_cast<double>(mesh.positions[3 * i + k]));
        }
    if (n > 0) model.accessors[position].minValues = lo, model.accessors[position].maxValues = hi;
    const int colour = addAccessor(model, mesh.colours, 3, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3,
                                   TINYGLTF_TARGET_ARRAY_BUFFER);
    const int scalar = addAccessor(model, mesh.scalar, 1, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_SCALAR,
                                   TINYGLTF_TARGET_ARRAY_BUFFER);
    const int index = addAccessor(model, mesh.indices, 1, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                                  TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);

    tinygltf::Material material;
    material.name = "lit (baked, unlit)";
    material.pbrMetallicRoughness.baseColorFactor = {1, 1, 1, 1};
    material.pbrMetallicRoughness.metallicFactor = 0;
    material.pbrMetallicRoughness.roughnessFactor = 1;
    material.extensions["KHR_materials_unlit"] = tinygltf::Value(tinygltf::Value::Object());
    model.materials.push_back(material);

    tinygltf::Primitive primitive;
    primitive.attributes["POSITION"] = position;
    primitive.attributes["COLOR_0"] = colour;
    primitive.attributes[mesh.scalarName] = scalar;
    primitive.indices = index;
    primitive.material = 0;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    tinygltf::Mesh gltfMesh;
    gltfMesh.name = "lit mesh";
    gltfMesh.primitives.push_back(primitive);
    model.meshes.push_back(gltfMesh);

    tinygltf::Node node;
    node.mesh = 0;
    node.name = "lit mesh";
    model.nodes.push_back(node);
    tinygltf::Scene scene;
    scene.nodes.push_back(0);
    if (camera) {
        tinygltf::Camera c;
        c.type = "perspective";
        c.perspective.yfov = camera->verticalFovRad;
        c.perspective.aspectRatio = camera->aspect;
        // The depth range: from 1 cm to twice the farthest vertex (tinygltf would write
        // zfar 0, which is invalid).
        double farthest = 1;
        for (size_t i = 0; i < n; ++i) {
            double d2 = 0;
            for (int k = 0; k < 3; ++k) d2 += std::pow(mesh.positions[3 * i + k] - camera->position[k], 2);
            farthest = std::max(farthest, std::sqrt(d2));
        }
        c.perspective.znear = 0.01;
        c.perspective.zfar = 2 * farthest;
        model.cameras.push_back(c);
        tinygltf::Node view;
        view.name = "view";
        view.camera = 0;
        view.translation.assign(camera->position, camera->position + 3);
        view.rotation.assign(camera->rotation, camera->rotation + 4);
        model.nodes.push_back(view);
        scene.nodes.push_back(1);
    }
    tinygltf::Value::Object fields;
    for (const auto& [key, value] : extras.text) fields[key] = tinygltf::Value(value);
    for (const auto& [key, value] : extras.numbers) fields[key] = tinygltf::Value(value);
    tinygltf::Value::Object wrapped;
    wrapped["rayrad"] = tinygltf::Value(fields);
    scene.extras = tinygltf::Value(wrapped);
    model.scenes.push_back(scene);
    model.defaultScene = 0;

    std::ostringstream out;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, out, /*prettyPrint=*/false, /*writeBinary=*/true))
        throw std::runtime_error("tinygltf could not encode the .glb");
    return out.str();
}

}  // namespace rayrad::scene
