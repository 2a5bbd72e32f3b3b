// Triangle meshes from OBJ/PLY/... files through assimp.
#pragma once

#include <core/math.h>

#include <string>
#include <vector>

namespace rayrad::scene {

struct ImportedMesh {
    std::vector<Vec3> positions;
    std::vector<std::vector<uint32_t>> triangles;
};

/// Reads every mesh in the file as triangles, in the file's own coordinates.
/// Throws InputError("<sceneFile>: <where>/file: ...") if it cannot be read.
ImportedMesh importMesh(const std::string& path, const std::string& sceneFile, const std::string& where);

}  // namespace rayrad::scene
