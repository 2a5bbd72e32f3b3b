#include <radiosity/patch_mesh.h>

#include <fmt/format.h>

#include <algorithm>

namespace rayrad::radiosity {

double PatchMesh::totalArea() const {
    double a = 0;
    for (const auto& p : patches) a += p.area;
    return a;
}

void computeGeometry(const PatchMesh& mesh, Patch& p) {
    computeGeometry({mesh.vertices[p.v[0]], mesh.vertices[p.v[1]], mesh.vertices[p.v[2]]}, p);
}

void computeGeometry(const std::array<Vec3, 3>& corners, Patch& p) {
    const Vec3 &a = corners[0], &b = corners[1], &c = corners[2];
    Vec3 n = glm::cross(b - a, c - a);
    double len = glm::length(n);
    p.area = 0.5 * len;
    p.normal = len > 0 ? n / len : Vec3(0.0);
    p.centroid = (a + b + c) / 3.0;
    p.diameter = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
}

std::string toString(const Patch& p) {
    return fmt::format("Patch{{v=[{},{},{}], area={:.6g} m², normal={}, material={}}}", p.v[0], p.v[1], p.v[2],
                       p.area, rayrad::toString(p.normal), p.material);
}

}  // namespace rayrad::radiosity
