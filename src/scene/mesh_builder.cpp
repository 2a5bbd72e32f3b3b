#include <scene/mesh_builder.h>

#include <scene/polygon.h>

namespace rayrad::scene {

uint32_t MeshBuilder::vertexAt(const Vec3& p) {
    auto key = std::make_tuple(p.x, p.y, p.z);
    auto it = m_vertexIndex.find(key);
    if (it != m_vertexIndex.end()) return it->second;
    auto id = static_cast<uint32_t>(m_out.positions.size());
    m_out.positions.push_back(p);
    m_vertexIndex.emplace(key, id);
    return id;
}

void MeshBuilder::addFace(const std::vector<uint32_t>& face, int material, const std::vector<glm::dvec2>& uvs) {
    if (face.size() == 3) {
        add(face, uvs, 0, 1, 2, material);
        return;
    }
    m_corners.clear();
    for (uint32_t i : face) m_corners.push_back(m_out.positions[i]);
    for (const auto& t : triangulate(m_corners)) add(face, uvs, t[0], t[1], t[2], material);
}

/// Corners a, b, c of the face.
void MeshBuilder::add(const std::vector<uint32_t>& face, const std::vector<glm::dvec2>& uvs, int a, int b, int c,
                      int material) {
    m_out.triangles.push_back({face[a], face[b], face[c]});
    m_out.triangleMaterial.push_back(material);
    if (uvs.size() == face.size()) {
        m_out.triangleUvs.resize(m_out.triangles.size() - 1);  // triangles before without coordinates: (0, 0)
        m_out.triangleUvs.push_back({uvs[a], uvs[b], uvs[c]});
    }
}

}  // namespace rayrad::scene
