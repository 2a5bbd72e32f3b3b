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

void MeshBuilder::addFace(const std::vector<uint32_t>& face, int material) {
    if (face.size() == 3) {
        add(face[0], face[1], face[2], material);
        return;
    }
    m_corners.clear();
    for (uint32_t i : face) m_corners.push_back(m_out.positions[i]);
    for (const auto& t : triangulate(m_corners)) add(face[t[0]], face[t[1]], face[t[2]], material);
}

void MeshBuilder::add(uint32_t a, uint32_t b, uint32_t c, int material) {
    m_out.triangles.push_back({a, b, c});
    m_out.triangleMaterial.push_back(material);
}

}  // namespace rayrad::scene
