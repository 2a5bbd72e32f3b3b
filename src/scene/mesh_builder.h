// Collects an imported mesh's triangles: one vertex per distinct position (so neighbouring
// triangles share corners whether or not the file did), polygons triangulated by ear
// clipping. Shared by the importers (assimp, PLY, glTF).
#pragma once

#include <scene/mesh_import.h>

#include <map>
#include <tuple>
#include <vector>

namespace rayrad::scene {

class MeshBuilder {
  public:
    explicit MeshBuilder(ImportedMesh& out) : m_out(out) {}

    /// The index of the vertex at p (finite; checked by the caller), added if new.
    uint32_t vertexAt(const Vec3& p);

    /// A face of 3 or more vertex indices (into the positions, checked by the caller);
    /// `material` indexes ImportedMesh::materials, or −1; `uvs`: the texture coordinates
    /// of the face's corners (empty: the file gives none).
    void addFace(const std::vector<uint32_t>& face, int material, const std::vector<glm::dvec2>& uvs = {});

  private:
    void add(const std::vector<uint32_t>& face, const std::vector<glm::dvec2>& uvs, int a, int b, int c, int material);

    ImportedMesh& m_out;
    std::map<std::tuple<double, double, double>, uint32_t> m_vertexIndex;
    std::vector<Vec3> m_corners;
};

}  // namespace rayrad::scene
