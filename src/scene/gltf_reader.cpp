#include <scene/gltf_reader.h>

#include <core/input_error.h>
#include <core/input_file.h>
#include <core/text.h>
#include <scene/mesh_builder.h>

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

// tinygltf: no image decoding (images are noted by name only) and no image writing.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

#include <cctype>
#include <cmath>
#include <cstring>

namespace rayrad::scene {

namespace {

/// Node visits (a node referenced by several parents is visited once per reference) and
/// triangles a file may make: far beyond any real model, short of exhausting memory.
constexpr size_t kMaxNodeVisits = 1'000'000;
constexpr size_t kMaxTriangles = 50'000'000;
constexpr int kMaxDepth = 256;

/// The elements of an accessor as bytes: element i starts at data + i · stride.
struct ElementView {
    const unsigned char* data = nullptr;
    size_t stride = 0;
    size_t count = 0;
    int componentType = 0;
};

size_t componentSize(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
        default: return 0;
    }
}

class GltfReader {
  public:
    GltfReader(const tinygltf::Model& model, std::string prefix, ImportedMesh& out)
        : m_model(model), m_prefix(std::move(prefix)), m_out(out) {}

    void read() {
        readMaterials();
        for (int node : rootNodes()) visit(node, glm::dmat4(1.0), 0);
    }

  private:
    [[noreturn]] void fail(const std::string& why) const { throw InputError(m_prefix + why); }

    /// The default scene's nodes; without scenes, every node no other node names as a child.
    std::vector<int> rootNodes() const {
        if (!m_model.scenes.empty()) {
            int s = m_model.defaultScene >= 0 ? m_model.defaultScene : 0;
            if (s >= static_cast<int>(m_model.scenes.size())) fail(fmt::format("the default scene {} does not exist", s));
            return m_model.scenes[s].nodes;
        }
        std::vector<bool> isChild(m_model.nodes.size(), false);
        for (const auto& n : m_model.nodes)
            for (int c : n.children)
                if (c >= 0 && c < static_cast<int>(isChild.size())) isChild[c] = true;
        std::vector<int> roots;
        for (size_t i = 0; i < isChild.size(); ++i)
            if (!isChild[i]) roots.push_back(static_cast<int>(i));
        return roots;
    }

    static std::vector<double> numbers(const std::vector<double>& v, size_t n, double fallback) {
        return v.size() == n ? v : std::vector<double>(n, fallback);
    }

    void readMaterials() {
        for (size_t i = 0; i < m_model.materials.size(); ++i) {
            const tinygltf::Material& m = m_model.materials[i];
            ImportedMaterial out;
            out.name = m.name.empty() ? fmt::format("material {}", i) : m.name;
            // The spec's default base colour is white.
            const auto base = numbers(m.pbrMetallicRoughness.baseColorFactor, 4, 1.0);
            out.reflectance = Rgb(base[0], base[1], base[2]);
            out.hasReflectance = true;
            const auto emissive = numbers(m.emissiveFactor, 3, 0.0);
            out.emission = Rgb(emissive[0], emissive[1], emissive[2]);
            auto strength = m.extensions.find("KHR_materials_emissive_strength");
            if (strength != m.extensions.end() && strength->second.Has("emissiveStrength") &&
                strength->second.Get("emissiveStrength").IsNumber()) {
                const double s = strength->second.Get("emissiveStrength").GetNumberAsDouble();
                if (std::isfinite(s) && s > 0) out.emission *= s;
            }
            if (!isFinite(out.reflectance) || !isFinite(out.emission))
                fail(fmt::format("material {} (\"{}\"): a colour is not finite", i, out.name));
            const int texture = m.pbrMetallicRoughness.baseColorTexture.index;
            if (texture >= 0 && texture < static_cast<int>(m_model.textures.size())) {
                const int image = m_model.textures[texture].source;
                if (image >= 0 && image < static_cast<int>(m_model.images.size()))
                    out.diffuseTexture = m_model.images[image].uri.empty() ? m_model.images[image].name : m_model.images[image].uri;
            }
            readSurfaceProperties(m, out);
            m_out.materials.push_back(std::move(out));
        }
    }

    /// What of the material rayrad honours besides its colour — doubleSided (two-sided),
    /// transmission (glass), polished metal (a mirror where flat: the builder) — and what
    /// it names instead: rough metal is read as diffuse with its base colour.
    void readSurfaceProperties(const tinygltf::Material& m, ImportedMaterial& out) {
        out.twoSided = m.doubleSided;
        auto number = [&](const char* extension, const char* key, double fallback) {
            auto e = m.extensions.find(extension);
            if (e == m.extensions.end() || !e->second.Has(key) || !e->second.Get(key).IsNumber()) return fallback;
            const double v = e->second.Get(key).GetNumberAsDouble();
            return std::isfinite(v) ? v : fallback;
        };
        if (m.extensions.count("KHR_materials_transmission") &&
            number("KHR_materials_transmission", "transmissionFactor", 0.0) >= 0.5) {
            out.glass = true;
            out.ior = std::clamp(number("KHR_materials_ior", "ior", 1.5), 1.0, 4.0);
            out.twoSided = false;
        }
        const double metallic = m.pbrMetallicRoughness.metallicFactor;
        out.mirrorLike = !out.glass && metallic >= 0.5 && m.pbrMetallicRoughness.roughnessFactor <= kMirrorRoughness;
        if (!out.glass && metallic >= 0.5 && !out.mirrorLike)
            m_out.materialWarnings.push_back(fmt::format(
                "material \"{}\" is metallic (metallicFactor {:g}, roughness {:g}): read as diffuse with its base "
                "colour (rayrad's mirrors are the scene file's quads, polygons and boxes)",
                out.name, metallic, m.pbrMetallicRoughness.roughnessFactor));
    }

    static glm::dmat4 localTransform(const tinygltf::Node& n) {
        if (n.matrix.size() == 16) return glm::make_mat4(n.matrix.data());  // column-major, as glTF
        const auto t = numbers(n.translation, 3, 0.0);
        const auto s = numbers(n.scale, 3, 1.0);
        const auto r = n.rotation.size() == 4 ? n.rotation : std::vector<double>{0, 0, 0, 1};  // x, y, z, w
        const glm::dquat q(r[3], r[0], r[1], r[2]);
        return glm::translate(glm::dmat4(1.0), Vec3(t[0], t[1], t[2])) * glm::mat4_cast(q) *
               glm::scale(glm::dmat4(1.0), Vec3(s[0], s[1], s[2]));
    }

    void visit(int index, const glm::dmat4& parent, int depth) {
        if (index < 0 || index >= static_cast<int>(m_model.nodes.size())) fail(fmt::format("node {} does not exist", index));
        if (depth > kMaxDepth) fail(fmt::format("the node hierarchy is deeper than {} levels (a cycle?)", kMaxDepth));
        if (++m_visits > kMaxNodeVisits)
            fail(fmt::format("the node hierarchy instances more than {} nodes", kMaxNodeVisits));
        const tinygltf::Node& node = m_model.nodes[index];
        const glm::dmat4 transform = parent * localTransform(node);
        for (int c = 0; c < 4; ++c)
            if (!isFinite(Vec3(transform[c])) || !std::isfinite(transform[c][3]))
                fail(fmt::format("node {}: its transform is not finite", index));
        if (node.mesh >= 0) {
            if (node.mesh >= static_cast<int>(m_model.meshes.size())) fail(fmt::format("node {}: mesh {} does not exist", index, node.mesh));
            for (const auto& primitive : m_model.meshes[node.mesh].primitives) addPrimitive(primitive, transform, node.mesh);
        }
        addLight(node, transform, index);
        addCamera(node, transform, index);
        for (int child : node.children) visit(child, transform, depth + 1);
    }

    /// The accessor's elements, checked to lie inside their buffer.
    ElementView elements(int accessorIndex, int wantType, const std::string& what) const {
        if (accessorIndex < 0 || accessorIndex >= static_cast<int>(m_model.accessors.size()))
            fail(fmt::format("{}: accessor {} does not exist", what, accessorIndex));
        const tinygltf::Accessor& a = m_model.accessors[accessorIndex];
        const std::string name = fmt::format("{} (accessor {})", what, accessorIndex);
        if (a.sparse.isSparse) fail(name + ": sparse accessors are not supported");
        if (a.type != wantType) fail(name + ": wrong element type");
        const size_t components = wantType == TINYGLTF_TYPE_VEC3 ? 3 : wantType == TINYGLTF_TYPE_VEC2 ? 2 : 1;
        const size_t elementSize = componentSize(a.componentType) * components;
        if (elementSize == 0) fail(fmt::format("{}: unknown component type {}", name, a.componentType));
        if (a.bufferView < 0 || a.bufferView >= static_cast<int>(m_model.bufferViews.size()))
            fail(name + ": it has no buffer view");
        const tinygltf::BufferView& view = m_model.bufferViews[a.bufferView];
        if (view.buffer < 0 || view.buffer >= static_cast<int>(m_model.buffers.size()))
            fail(fmt::format("{}: buffer {} does not exist", name, view.buffer));
        const std::vector<unsigned char>& buffer = m_model.buffers[view.buffer].data;
        const size_t stride = view.byteStride > 0 ? view.byteStride : elementSize;
        if (stride < elementSize) fail(name + ": its byte stride is shorter than an element");
        // The view inside the buffer, the elements inside the view; no sum may overflow.
        if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset)
            fail(name + ": its buffer view reaches past the end of its buffer");
        ElementView out;
        out.count = a.count;
        out.stride = stride;
        out.componentType = a.componentType;
        if (a.count == 0) return out;
        if (a.byteOffset > view.byteLength || (a.count - 1) > (view.byteLength - a.byteOffset) / stride ||
            (a.count - 1) * stride + elementSize > view.byteLength - a.byteOffset)
            fail(fmt::format("{}: {} elements reach past the end of its buffer view", name, a.count));
        out.data = buffer.data() + view.byteOffset + a.byteOffset;
        return out;
    }

    static uint32_t indexAt(const ElementView& v, size_t i) {
        const unsigned char* p = v.data + i * v.stride;
        switch (v.componentType) {
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return p[0];
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
                uint16_t x;
                std::memcpy(&x, p, 2);
                return x;
            }
            default: {
                uint32_t x;
                std::memcpy(&x, p, 4);
                return x;
            }
        }
    }

    void addPrimitive(const tinygltf::Primitive& primitive, const glm::dmat4& transform, int mesh) {
        const std::string what = fmt::format("mesh {}", mesh);
        const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
        auto position = primitive.attributes.find("POSITION");
        if (position == primitive.attributes.end()) fail(what + ": a primitive has no POSITION");
        const ElementView points = elements(position->second, TINYGLTF_TYPE_VEC3, what + " POSITION");
        if (points.count > 0 && points.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
            fail(what + ": POSITION must be float");
        std::vector<uint32_t> vertex(points.count);
        for (size_t v = 0; v < points.count; ++v) {
            float xyz[3];
            std::memcpy(xyz, points.data + v * points.stride, sizeof xyz);
            const Vec3 p = Vec3(transform * glm::dvec4(xyz[0], xyz[1], xyz[2], 1.0));
            if (!isFinite(p)) fail(fmt::format("{}: vertex {} is not finite", what, v));
            vertex[v] = m_builder.vertexAt(p);
        }
        // Texture coordinates (float; glTF's t runs down the image, rayrad's v up it).
        std::vector<glm::dvec2> uv;
        auto texcoord = primitive.attributes.find("TEXCOORD_0");
        if (texcoord != primitive.attributes.end()) {
            const ElementView t = elements(texcoord->second, TINYGLTF_TYPE_VEC2, what + " TEXCOORD_0");
            if (t.count != points.count) fail(what + ": TEXCOORD_0 and POSITION differ in count");
            if (t.count > 0 && t.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
                fail(what + ": only float TEXCOORD_0 is read");
            uv.resize(t.count);
            for (size_t v = 0; v < t.count; ++v) {
                float st[2];
                std::memcpy(st, t.data + v * t.stride, sizeof st);
                if (!std::isfinite(st[0]) || !std::isfinite(st[1])) fail(fmt::format("{}: texture coordinate {} is not finite", what, v));
                uv[v] = glm::dvec2(st[0], 1.0 - st[1]);
            }
        }
        // The corner list: the indices, or 0 … n−1 without them.
        std::vector<uint32_t> corners;
        if (primitive.indices >= 0) {
            const ElementView idx = elements(primitive.indices, TINYGLTF_TYPE_SCALAR, what + " indices");
            if (idx.count > 0 && idx.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                idx.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                idx.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
                fail(what + ": indices must be unsigned integers");
            corners.resize(idx.count);
            for (size_t i = 0; i < idx.count; ++i) corners[i] = indexAt(idx, i);
        } else {
            corners.resize(points.count);
            for (size_t i = 0; i < points.count; ++i) corners[i] = static_cast<uint32_t>(i);
        }
        int material = primitive.material;
        if (material >= static_cast<int>(m_out.materials.size())) fail(fmt::format("{}: material {} does not exist", what, material));
        if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) {
            m_out.droppedFaces += corners.size();  // points and lines carry no area
            return;
        }
        // A node whose transform mirrors (negative determinant) reverses the winding, as the
        // glTF specification says: else its triangles would face inward.
        const bool mirrored = glm::determinant(glm::dmat3(transform)) < 0;
        const size_t triangles = mode == TINYGLTF_MODE_TRIANGLES ? corners.size() / 3 : (corners.size() >= 3 ? corners.size() - 2 : 0);
        if (m_out.triangles.size() + triangles > kMaxTriangles)
            fail(fmt::format("the file makes more than {} triangles", kMaxTriangles));
        std::vector<uint32_t> face(3);
        for (size_t t = 0; t < triangles; ++t) {
            uint32_t c[3];
            if (mode == TINYGLTF_MODE_TRIANGLES) {
                c[0] = corners[3 * t], c[1] = corners[3 * t + 1], c[2] = corners[3 * t + 2];
            } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {  // odd triangles are wound the other way
                c[0] = corners[t], c[1] = corners[t % 2 ? t + 2 : t + 1], c[2] = corners[t % 2 ? t + 1 : t + 2];
            } else {
                c[0] = corners[0], c[1] = corners[t + 1], c[2] = corners[t + 2];
            }
            if (c[0] >= points.count || c[1] >= points.count || c[2] >= points.count) {
                ++m_out.droppedFaces;  // an index past the vertices is broken data
                continue;
            }
            if (mirrored) std::swap(c[1], c[2]);
            for (int k = 0; k < 3; ++k) face[k] = vertex[c[k]];
            if (uv.empty()) {
                m_builder.addFace(face, material);
            } else {
                m_builder.addFace(face, material, {uv[c[0]], uv[c[1]], uv[c[2]]});
            }
        }
    }

    /// A node's camera: at the node's origin, looking down its −z with +y up.
    void addCamera(const tinygltf::Node& node, const glm::dmat4& transform, int index) {
        if (node.camera < 0) return;
        if (node.camera >= static_cast<int>(m_model.cameras.size()))
            fail(fmt::format("node {}: camera {} does not exist", index, node.camera));
        const tinygltf::Camera& in = m_model.cameras[node.camera];
        ImportedCamera c;
        c.name = !in.name.empty() ? in.name : !node.name.empty() ? node.name : fmt::format("camera {}", node.camera);
        c.position = Vec3(transform * glm::dvec4(0, 0, 0, 1));
        const auto direction = unitDirection(glm::dmat3(transform) * Vec3(0, 0, -1));
        const auto up = unitDirection(glm::dmat3(transform) * Vec3(0, 1, 0));
        if (!direction || !up || std::abs(glm::dot(*direction, *up)) > 1 - 1e-9)
            fail(fmt::format("node {}: camera \"{}\" has a degenerate transform", index, c.name));
        c.direction = *direction;
        c.up = *up;
        if (in.type == "orthographic") {
            c.orthographic = true;
            c.ymag = std::abs(in.orthographic.ymag);
            if (in.orthographic.ymag != 0) c.aspectRatio = std::abs(in.orthographic.xmag / in.orthographic.ymag);
            if (!(c.ymag > 0) || !std::isfinite(c.ymag)) fail(fmt::format("camera \"{}\": ymag must be positive", c.name));
        } else {
            c.yfovDeg = in.perspective.yfov * 180 / kPi;
            c.aspectRatio = in.perspective.aspectRatio;
            if (!(c.yfovDeg > 0 && c.yfovDeg < 180))
                fail(fmt::format("camera \"{}\": yfov {:g} rad is not between 0 and π", c.name, in.perspective.yfov));
        }
        if (!(c.aspectRatio > 0 && c.aspectRatio < 100)) c.aspectRatio = 0;
        m_out.cameras.push_back(c);
    }

    void addLight(const tinygltf::Node& node, const glm::dmat4& transform, int index) {
        auto ext = node.extensions.find("KHR_lights_punctual");
        if (ext == node.extensions.end() || !ext->second.Has("light") || !ext->second.Get("light").IsNumber()) return;
        const int l = ext->second.Get("light").GetNumberAsInt();
        if (l < 0 || l >= static_cast<int>(m_model.lights.size())) fail(fmt::format("node {}: light {} does not exist", index, l));
        const tinygltf::Light& in = m_model.lights[l];
        const std::string name = in.name.empty() ? fmt::format("light {}", l) : "\"" + in.name + "\"";
        if (in.type != "point" && in.type != "spot") {
            m_out.warnings.push_back(fmt::format("{} is {}: left out (rayrad has point and spot lights)", name,
                                                 in.type.empty() ? "of no type" : in.type));
            return;
        }
        ImportedLight light;
        light.name = in.name;
        light.isSpot = in.type == "spot";
        light.position = Vec3(transform * glm::dvec4(0, 0, 0, 1));
        const Vec3 d = glm::dmat3(transform) * Vec3(0, 0, -1);  // a glTF light shines along its −z
        if (glm::length(d) > 0) light.direction = glm::normalize(d);
        // Point and spot intensities are candela in glTF.
        const auto colour = numbers(in.color, 3, 1.0);
        light.intensity = Rgb(colour[0], colour[1], colour[2]) * in.intensity;
        light.innerAngleDeg = glm::degrees(in.spot.innerConeAngle);
        light.outerAngleDeg = glm::degrees(in.spot.outerConeAngle);
        if (!isFinite(light.position) || !isFinite(light.intensity) || light.intensity.r < 0 || light.intensity.g < 0 ||
            light.intensity.b < 0) {
            m_out.warnings.push_back(fmt::format("{}: its intensity ({:g} × colour) is negative or not finite: left out",
                                                 name, in.intensity));
            return;
        }
        m_out.lights.push_back(light);
    }

    const tinygltf::Model& m_model;
    std::string m_prefix;
    ImportedMesh& m_out;
    MeshBuilder m_builder{m_out};
    size_t m_visits = 0;
};

/// tinygltf's messages, one line.
std::string oneLine(std::string text) {
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
    for (auto& c : text)
        if (c == '\n') c = ';';
    return text.size() > 300 ? text.substr(0, 297) + "..." : text;
}

bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
    return true;  // images are not decoded: only their names are kept
}

/// tinygltf's file reading, noting the files it reads that are Git LFS pointers (a .bin
/// buffer of a repository cloned without Git LFS): a size mismatch is all tinygltf says.
bool readNotingLfsPointers(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                           void* pointers) {
    if (!tinygltf::ReadWholeFile(out, err, path, nullptr)) return false;
    if (isGitLfsPointer(std::string_view(reinterpret_cast<const char*>(out->data()), out->size())))
        static_cast<std::vector<std::string>*>(pointers)->push_back(path);
    return true;
}

}  // namespace

ImportedMesh readGltf(const std::string& path, const std::string& errorPrefix) {
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(skipImage, nullptr);
    std::vector<std::string> lfsPointers;
    loader.SetFsCallbacks({&tinygltf::FileExists, &tinygltf::ExpandFilePath, &readNotingLfsPointers,
                           &tinygltf::WriteWholeFile, &lfsPointers});
    tinygltf::Model model;
    std::string error, warning;
    const std::string ext = lowerExtension(path);
    bool ok = false;
    try {
        ok = ext == ".glb" ? loader.LoadBinaryFromFile(&model, &error, &warning, path)
                           : loader.LoadASCIIFromFile(&model, &error, &warning, path);
    } catch (const nlohmann::json::exception& e) {  // tinygltf reading a value of an unexpected type
        throw InputError(errorPrefix + "not a valid glTF 2.0 file: " + e.what());
    }
    if (!lfsPointers.empty())
        throw InputError(errorPrefix + "its file '" + lfsPointers.front() + "' " + kGitLfsPointerProblem);
    if (!ok) throw InputError(errorPrefix + "not a valid glTF 2.0 file: " + oneLine(error.empty() ? warning : error));
    ImportedMesh out;
    GltfReader(model, errorPrefix, out).read();
    return out;
}

}  // namespace rayrad::scene
