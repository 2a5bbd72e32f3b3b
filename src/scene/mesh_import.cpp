#include <scene/mesh_import.h>

#include <core/input_error.h>
#include <core/input_file.h>
#include <core/text.h>
#include <scene/gltf_reader.h>
#include <scene/mesh_builder.h>
#include <scene/ply_reader.h>
#include <scene/polygon.h>

#include <assimp/material.h>
#include <assimp/scene.h>
#include <assimp/version.h>
#include <assimp/Importer.hpp>

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

namespace rayrad::scene {

namespace {

/// The file's material m, or nothing usable (assimp's stand-in "DefaultMaterial" for
/// files without materials counts as none).
ImportedMaterial readMaterial(const aiMaterial* m) {
    ImportedMaterial out;
    aiString name;
    if (m->Get(AI_MATKEY_NAME, name) == AI_SUCCESS) out.name = name.C_Str();
    if (out.name == AI_DEFAULT_MATERIAL_NAME) return out;
    aiColor4D base;
    aiColor3D c;
    // glTF's baseColorFactor first (assimp also copies it to the diffuse colour), then Kd.
    if (m->Get(AI_MATKEY_BASE_COLOR, base) == AI_SUCCESS) {
        out.reflectance = Rgb(base.r, base.g, base.b);
        out.hasReflectance = true;
    } else if (m->Get(AI_MATKEY_COLOR_DIFFUSE, c) == AI_SUCCESS) {
        out.reflectance = Rgb(c.r, c.g, c.b);
        out.hasReflectance = true;
    }
    if (m->Get(AI_MATKEY_COLOR_EMISSIVE, c) == AI_SUCCESS) {
        out.emission = Rgb(c.r, c.g, c.b);
        float strength = 1;
        if (m->Get(AI_MATKEY_EMISSIVE_INTENSITY, strength) == AI_SUCCESS && std::isfinite(strength) && strength > 0)
            out.emission *= static_cast<double>(strength);
    }
    aiString texture;
    if (m->GetTexture(aiTextureType_DIFFUSE, 0, &texture) == AI_SUCCESS ||
        m->GetTexture(aiTextureType_BASE_COLOR, 0, &texture) == AI_SUCCESS)
        out.diffuseTexture = texture.C_Str();
    return out;
}

Vec3 toVec3(const aiVector3D& v) {
    return Vec3(v.x, v.y, v.z);
}

/// Walks the node tree, appending every mesh a node references with the node's
/// accumulated transform. Each mesh's data is checked before it is used.
class MeshCollector {
  public:
    /// `materialOf`: assimp material index → ImportedMesh::materials index, or −1.
    MeshCollector(const aiScene& scene, ImportedMesh& out, std::vector<int> materialOf, std::string errorPrefix)
        : m_scene(scene), m_out(out), m_materialOf(std::move(materialOf)), m_prefix(std::move(errorPrefix)) {}

    void visit(const aiNode* node, const aiMatrix4x4& parent, int depth) {
        if (!node) return;
        if (depth > 256) throw InputError(m_prefix + "the node hierarchy is deeper than 256 levels (a cycle?)");
        const aiMatrix4x4 transform = parent * node->mTransformation;
        m_nodeTransforms[node->mName.C_Str()] = transform;
        for (unsigned k = 0; k < node->mNumMeshes; ++k) {
            unsigned m = node->mMeshes ? node->mMeshes[k] : m_scene.mNumMeshes;
            if (m >= m_scene.mNumMeshes || !m_scene.mMeshes || !m_scene.mMeshes[m]) {
                ++m_out.droppedFaces;
                continue;
            }
            addMesh(*m_scene.mMeshes[m], transform);
        }
        for (unsigned k = 0; k < node->mNumChildren; ++k)
            if (node->mChildren) visit(node->mChildren[k], transform, depth + 1);
    }

    /// Node transform by name (lights are placed by the node of the same name).
    const aiMatrix4x4* nodeTransform(const std::string& name) const {
        auto it = m_nodeTransforms.find(name);
        return it == m_nodeTransforms.end() ? nullptr : &it->second;
    }

  private:
    void addMesh(const aiMesh& mesh, const aiMatrix4x4& transform) {
        if (!mesh.mVertices || mesh.mNumVertices == 0 || !mesh.mFaces) {
            m_out.droppedFaces += mesh.mNumFaces;
            return;
        }
        std::vector<uint32_t> index(mesh.mNumVertices);
        for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
            Vec3 p = toVec3(transform * mesh.mVertices[v]);
            if (!isFinite(p)) throw InputError(m_prefix + fmt::format("vertex {} is not finite", v));
            index[v] = m_builder.vertexAt(p);
        }
        int material = -1;
        if (mesh.mMaterialIndex < m_materialOf.size()) material = m_materialOf[mesh.mMaterialIndex];
        std::vector<uint32_t> face;
        std::vector<glm::dvec2> uvs;
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& in = mesh.mFaces[f];
            bool valid = in.mNumIndices >= 3 && in.mIndices;
            for (unsigned k = 0; valid && k < in.mNumIndices; ++k) valid = in.mIndices[k] < mesh.mNumVertices;
            if (!valid) {  // points and lines carry no area; out-of-range indices are broken data
                ++m_out.droppedFaces;
                continue;
            }
            face.clear();
            uvs.clear();
            for (unsigned k = 0; k < in.mNumIndices; ++k) {
                face.push_back(index[in.mIndices[k]]);
                if (mesh.mTextureCoords[0]) {
                    const aiVector3D& t = mesh.mTextureCoords[0][in.mIndices[k]];
                    if (!std::isfinite(t.x) || !std::isfinite(t.y))
                        throw InputError(m_prefix + fmt::format("texture coordinate {} is not finite", in.mIndices[k]));
                    uvs.emplace_back(t.x, t.y);
                }
            }
            m_builder.addFace(face, material, uvs);
        }
    }

    const aiScene& m_scene;
    ImportedMesh& m_out;
    std::vector<int> m_materialOf;
    MeshBuilder m_builder{m_out};
    std::string m_prefix;
    std::map<std::string, aiMatrix4x4> m_nodeTransforms;
};

/// A PLY file through rayrad's own reader (assimp's crashes on some binary PLY files).
ImportedMesh importPly(const std::string& path, const std::string& prefix) {
    PlyMesh ply;
    try {
        ply = readPly(path);
    } catch (const std::exception& e) {
        throw InputError(prefix + e.what());
    }
    ImportedMesh out;
    MeshBuilder builder(out);
    std::vector<uint32_t> index(ply.positions.size());
    for (size_t v = 0; v < ply.positions.size(); ++v) {
        if (!isFinite(ply.positions[v])) throw InputError(prefix + fmt::format("vertex {} is not finite", v));
        index[v] = builder.vertexAt(ply.positions[v]);
    }
    std::vector<uint32_t> face;
    for (const auto& f : ply.faces) {
        bool valid = f.size() >= 3;
        for (uint32_t i : f) valid = valid && i < ply.positions.size();
        if (!valid) {
            ++out.droppedFaces;
            continue;
        }
        face.clear();
        for (uint32_t i : f) face.push_back(index[i]);
        builder.addFace(face, -1);
    }
    return out;
}

bool hasExtension(const std::string& path, const std::string& ext) {
    return lowerExtension(path) == ext;
}

/// Why a mesh file gave no triangle: none in it, or every face it has was left out.
std::string noTriangles(const std::string& path, const ImportedMesh& mesh) {
    if (mesh.droppedFaces == 0) return "mesh '" + path + "' has no triangles";
    return fmt::format(
        "mesh '{}' has no triangles: its {} face(s) are points or lines, or name vertices the file does "
        "not have",
        path, mesh.droppedFaces);
}

}  // namespace

/// The OBJ's `mtllib` files that are not there, one warning each: assimp then gives every
/// material its default grey and no emission, without a word.
static std::vector<std::string> missingMaterialLibraries(const std::string& path) {
    std::vector<std::string> out;
    std::ifstream in(path);
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
        const size_t at = line.find_first_not_of(" \t");
        if (at == std::string::npos || line.compare(at, 7, "mtllib ") != 0) continue;
        std::string name = line.substr(at + 7);
        while (!name.empty() && std::isspace(static_cast<unsigned char>(name.back()))) name.pop_back();
        while (!name.empty() && std::isspace(static_cast<unsigned char>(name.front()))) name.erase(0, 1);
        const std::string library = (std::filesystem::path(path).parent_path() / name).string();
        if (const std::string problem = inputFileProblem(library, "material library"); !problem.empty())
            out.push_back(
                fmt::format("line {}: material library {}: {} (every material of the file is read as "
                            "a default grey, and its lamps do not glow)",
                            n, library, problem));
    }
    return out;
}

ImportedMesh importMesh(const std::string& path, const std::string& sceneFile, const std::string& where) {
    const std::string place = where + "/file";
    const std::string prefix = placeMessage(sceneFile, place, "mesh '" + path + "': ");
    if (std::string problem = inputFileProblem(path, "mesh file"); !problem.empty())
        throw InputError(placeMessage(sceneFile, place, "mesh file '" + path + "': " + problem));
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw InputError(placeMessage(sceneFile, place, "mesh file '" + path + "' is not a regular file"));
    if (hasExtension(path, ".gltf") || hasExtension(path, ".glb")) {
        ImportedMesh out = readGltf(path, prefix);
        if (out.triangles.empty()) throw InputError(placeMessage(sceneFile, place, noTriangles(path, out)));
        return out;
    }
    if (hasExtension(path, ".ply")) {
        ImportedMesh out = importPly(path, prefix);
        if (out.triangles.empty()) throw InputError(placeMessage(sceneFile, place, noTriangles(path, out)));
        return out;
    }
    ImportedMesh out;
    if (hasExtension(path, ".obj")) out.materialWarnings = missingMaterialLibraries(path);
    Assimp::Importer importer;
    // No post-processing at all: assimp's Triangulate asserts and JoinIdenticalVertices
    // segfaults on some binary PLY files. The collector checks, triangulates and joins.
    const aiScene* s = importer.ReadFile(path, 0);
    if (!s || !s->mRootNode)
        throw InputError(
            placeMessage(sceneFile, place, "cannot read mesh '" + path + "': " + importer.GetErrorString()));
    std::vector<int> materialOf;
    for (unsigned m = 0; m < s->mNumMaterials && s->mMaterials; ++m) {
        ImportedMaterial mat = s->mMaterials[m] ? readMaterial(s->mMaterials[m]) : ImportedMaterial{};
        bool usable = mat.hasReflectance || mat.emission != Rgb(0.0);
        materialOf.push_back(usable ? static_cast<int>(out.materials.size()) : -1);
        if (usable) out.materials.push_back(std::move(mat));
    }
    MeshCollector collector(*s, out, std::move(materialOf), prefix);
    collector.visit(s->mRootNode, aiMatrix4x4(), 0);
    for (unsigned l = 0; l < s->mNumLights && s->mLights; ++l) {
        const aiLight* a = s->mLights[l];
        if (!a || (a->mType != aiLightSource_POINT && a->mType != aiLightSource_SPOT)) continue;
        ImportedLight light;
        light.name = a->mName.C_Str();
        light.isSpot = a->mType == aiLightSource_SPOT;
        aiMatrix4x4 m;
        if (const aiMatrix4x4* t = collector.nodeTransform(light.name)) m = *t;
        light.position = toVec3(m * a->mPosition);
        aiMatrix3x3 rotation(m);
        Vec3 d = toVec3(rotation * a->mDirection);
        if (glm::length(d) > 0) light.direction = glm::normalize(d);
        // glTF intensities are candela for point and spot lights; assimp folds the
        // intensity into the colour.
        light.intensity = Rgb(a->mColorDiffuse.r, a->mColorDiffuse.g, a->mColorDiffuse.b);
        light.innerAngleDeg = glm::degrees(static_cast<double>(a->mAngleInnerCone));
        light.outerAngleDeg = glm::degrees(static_cast<double>(a->mAngleOuterCone));
        if (!isFinite(light.position) || !isFinite(light.intensity)) continue;
        out.lights.push_back(light);
    }
    if (out.triangles.empty()) throw InputError(placeMessage(sceneFile, place, noTriangles(path, out)));
    return out;
}

std::string assimpVersion() {
    return "Assimp " + std::to_string(aiGetVersionMajor()) + "." + std::to_string(aiGetVersionMinor()) + "." +
           std::to_string(aiGetVersionPatch());
}

}  // namespace rayrad::scene
