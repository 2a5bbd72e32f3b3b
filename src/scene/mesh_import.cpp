#include <scene/mesh_import.h>

#include <core/input_error.h>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <cmath>
#include <filesystem>

namespace rayrad::scene {

ImportedMesh importMesh(const std::string& path, const std::string& sceneFile, const std::string& where) {
    const std::string place = where + "/file";
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw InputError(placeMessage(sceneFile, place, "mesh file '" + path + "' does not exist"));
    Assimp::Importer importer;
    // Keep vertices as written: no smoothing, no normal generation, only triangulation.
    const aiScene* s = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                                   aiProcess_FindDegenerates);
    if (!s || !s->mRootNode)
        throw InputError(placeMessage(sceneFile, place, "cannot read mesh '" + path + "': " + importer.GetErrorString()));
    ImportedMesh out;
    for (unsigned m = 0; m < s->mNumMeshes; ++m) {
        const aiMesh* mesh = s->mMeshes[m];
        auto base = static_cast<uint32_t>(out.positions.size());
        for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
            const aiVector3D& p = mesh->mVertices[v];
            Vec3 q(p.x, p.y, p.z);
            if (!isFinite(q))
                throw InputError(placeMessage(sceneFile, place, "mesh '" + path + "' has a non-finite vertex"));
            out.positions.push_back(q);
        }
        for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
            const aiFace& face = mesh->mFaces[f];
            if (face.mNumIndices != 3) continue;  // points and lines carry no area
            out.triangles.push_back({base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]});
        }
    }
    if (out.triangles.empty())
        throw InputError(placeMessage(sceneFile, place, "mesh '" + path + "' has no triangles"));
    return out;
}

}  // namespace rayrad::scene
